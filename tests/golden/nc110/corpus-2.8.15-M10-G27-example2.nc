; Corpus copy of part2/2.8.15-M10-G27-example2.nc (seed §2.8.15, L4620-4665), example 2.
; Continuous mode (G27): the block with M10 (N10) must name every axis the profile moves;
; it names X and Y (Y100 does not move), so X and Y stay unlocked for the whole profile;
; M11 in N14 cancels the lock.
; Changed: the list marker "2)" and the dotted elision after N14 are dropped; N14's
; elided "X.. Y.." are supplied as X0 Y0.
; Expected (decisions 44, 47): N10 clamp on before its move; N11-N13 move X and Y, no
; drive fault; N14 is a G00 move, which ends the profile, so M11 may stand in it: clamp
; off (and rotary_off) before the rapid. The variant with N10 naming only X is
; corpus-2.8.15-M10-G27-unnamed.
N9 G G27 X100 Y100
N10 G1 X-100 Y100 M10 F250
N11 Y-100
N12 X100
N13 Y100
N14 G X0 Y0 M11
