; Corpus copy of part2/2.8.15-M10-G29-example1.nc (seed §2.8.15, L4620-4665), example 1.
; Point-to-point (G29): no special care with M10; M11 in N14 cancels the lock.
; Changed: the list marker "1)" and the dotted elision after N14 are dropped; N14's
; elided "X.. Y.." are supplied as X0 Y0. The manual's prose says only the moving axis "Z"
; stays unlocked: a misprint for X, the only axis N10 names (nc110-corpus.md §G).
; Expected (decision 47): M10 acts at the start of N10 (Table 2.3) and clamps every axis
; N10 does not name (all but X); under G29 N11 and N13 still move Y (no drive fault, the
; rule is for G27/G28); M11 at the start of N14 unclamps all (clamp off, rotary_off).
N8  G G29 X100 Y100
N10 G1 X-100 M10 F250
N11 Y-100
N12 X100
N13 Y100
N14 G X0 Y0 M11
