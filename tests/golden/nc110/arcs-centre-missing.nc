; An arc with only one of I and J (§2.8.1.4 L2330: both are always present; decision 39:
; "both are needed"). G29: no G27 profile rule.
; Expected (ncc check): NC4004 at 7:1 and 8:1, a message that names the missing word,
; e.g. "clockwise arc in the XY plane needs its centre I J: J is not programmed" (and "I
; is not programmed"), not "none of I J is programmed" while one is.
N0 G29 G1 X10 Y0 F100
N1 G2 X0 Y10 I0
N2 G2 X10 Y0 J0
