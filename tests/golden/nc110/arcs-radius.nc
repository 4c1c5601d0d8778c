; Arcs by their radius (§2.8.1.4, L2437-2445, Fig. 2.6; decision 39): R+ gives the arc up
; to 180 degrees, R- the longer one; an unsigned R is R+; an E parameter's sign counts.
; All from X0 Y0 to X20 Y20 unless said; G29: no G27 profile rule.
; N1 G02 R+20: centre X20 Y0, cw 90.      N3 G02 R-20: centre X0 Y20, cw 270.
; N5 G03 R+20: centre X0 Y20, ccw 90.     N7 G03 R-20: centre X20 Y0, ccw 270.
; N9 G03 R20 (unsigned = R+): centre X0 Y20, ccw 90.
; N11 G02 RE30 with E30 = -20: as R-20, centre X0 Y20, cw 270.
; N13 G02 X40 Y0 R20: the chord is the diameter: centre X20 Y0, cw 180.
; N15 G02 X40.005 Y0 R20: the chord exceeds 2R by 0.005, within the arc tolerance 0.01:
;   a half circle about the chord's middle X20.0025 Y0, radius 20.0025.
N0 G29 G0 X0 Y0
N1 G02 X20 Y20 R+20 F100
N2 G0 X0 Y0
N3 G02 X20 Y20 R-20
N4 G0 X0 Y0
N5 G03 X20 Y20 R+20
N6 G0 X0 Y0
N7 G03 X20 Y20 R-20
N8 G0 X0 Y0
N9 G03 X20 Y20 R20
N10 G0 X0 Y0
E30 = -20
N11 G02 X20 Y20 RE30
N12 G0 X0 Y0
N13 G02 X40 Y0 R20
N14 G0 X0 Y0
N15 G02 X40.005 Y0 R20
