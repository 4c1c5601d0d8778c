; Variant of corpus-2.8.15-M10-G27-example2 (seed §2.8.15, L4630-4640): N10 names only X,
; so M10 clamps Y; under G27 N11 moves the clamped Y: «СБОЙ ПРИВОДА» (drive fault),
; NC4055 at N11 (decision 47), and again at N13. The other blocks are as in example 2.
; Expected (ncc check): NC4055 at 7:5 (the Y word of N11) and 9:5 (N13).
N9 G G27 X100 Y100
N10 G1 X-100 M10 F250
N11 Y-100
N12 X100
N13 Y100
N14 G X0 Y0 M11
