; Arc errors (§2.8.1.4, L2320-2445; decisions 28, 39). ncc check; after an error the dry
; run goes on as if the block had reached its end point. G29: no G27 profile rule.
; Expected:
;  N2 no centre and no radius: NC4004 "clockwise arc in the XY plane needs its centre
;     I J: none of them is programmed" (20:1).
;  N4 centre and radius: NC4066 "an arc is given by its centre I J or by its radius R,
;     not both" (22:1).
;  N6 chord 30 > 2R: NC4066 "the end point is 30 away, more than the diameter 20 of R10"
;     (24:1).
;  N8 a full circle by its radius: NC4066 "an arc by its radius cannot be a full circle:
;     give its centre with I J" (26:1).
;  N9 centre on the start: NC4005 at the I word (27:15).
;  N11 end radius 10.01 against 10: difference 0.01, the tolerance: no error.
;  N13 end radius 10.011: NC4003 "... start radius 10, end radius 10.011, difference 0.011
;     exceeds the tolerance 0.01" (31:1).
;  N16 X scaled by 2, Y by 1: NC4058 "an arc scaled by 2 along X and by 1 along Y would be
;     an ellipse" (34:1).
N0 G29 G0 X10 Y0
N1 G1 X10 Y0 F100
N2 G2 X0 Y10
N3 G0 X10 Y0
N4 G2 X0 Y10 I0 J0 R10
N5 G0 X10 Y0
N6 G2 X40 Y0 R10
N7 G0 X10 Y0
N8 G2 X10 Y0 R10
N9 G3 X0 Y-10 I10 J0
N10 G0 X10 Y0
N11 G2 X0 Y10.01 I0 J0
N12 G0 X10 Y0
N13 G2 X0 Y10.011 I0 J0
N14 G0 X10 Y0
N15 (SCF,2,X)
N16 G2 X0 Y10 I0 J0
N17 (SCF)
