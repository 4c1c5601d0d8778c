; comp-errors: what a compensated path may not hold (§2.8.7), each once at its block
; under ncc check (decision 74): a fillet whose sign is against the turn (r5 where the
; path turns clockwise: r-5); a fillet smaller than the tool on its inside; r with a
; move in its block; b of 0; an S word inside the profile (rule 2; under G29, where a
; G27 profile's rule does not say it first); r and b outside G41/G42 and GTL; u with
; G41 (§2.9).
N1 G29 T1.1 M6 S1000 M3 F200
N2 G X-20 Y20
N3 G1 G41 X0 Y0
N4 X100
N5 r5
N6 Y-100
N7 G40 X0
N8 G X-20 Y20
N9 G1 G41 X0 Y0
N10 X100
N11 r2
N12 Y100
N13 G40 X0
N14 G X-20 Y20
N15 G1 G41 X0 Y0
N16 X100
N17 r3 X5
N18 b0
N19 X110 S200
N20 X120 u1
N21 G40 X130
N22 X140
N23 r2
N24 b3
