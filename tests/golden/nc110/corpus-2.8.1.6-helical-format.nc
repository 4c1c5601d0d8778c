; Corpus copy of part2/2.8.1.6-helical-format-example.nc (seed §2.8.1.6, L2513-2522), as
; printed: a format line with '..' placeholders and the Russian "или" (or), not a block.
; The manual: X..Y..I..J.. the circle, Z the helix depth, K the pitch (K may be omitted
; when the depth is less than a pitch). Helices are tested in arcs-helix*.
; Expected: ncc check rejects the line once: the '(' at column 4 opens a code after ISO
; words, NC1028 "a block holds one instruction: a three-letter code after other words".
G02(или)G03 X..Y..Z..I..J..K..F.. ,
