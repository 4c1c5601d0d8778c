; What ends a G27 profile (§2.8.5 L3056-3063; decision 44 as updated: "M, S or T inside it
; is an error, except the program stops and ends (M00 M01 M02 M30), which end it"; "a G00
; move" ends it). The manual's example corpus-2.8.15-M10-G27-example2 writes M11 in the
; G00 block N14 of a G27 profile.
; Expected (ncc check): no error at all: N2 M11 stands in the G00 move that ends the
; profile; N4 M00 and N6 M30 are program stops and ends.
N1 G1 X10 F100
N2 G0 X0 M11
N3 G1 X10
N4 M00
N5 G1 X20
N6 M30
