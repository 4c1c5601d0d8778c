; graphic-display: the graphic display of §2.13.7 (corpus part4/2.13.7.1-UCG-example-2.nc,
; its CZ200 read as Z200, and 2.13.7.3-CLG-DCG-example.nc), recorded in the trace as
; `graphic` events a picture of the run can draw (decision 79): the field of UCG, from
; the current origin, in mode 1..3 with the third axis it marks; CLG clears it; DCG
; switches it off. The manual's rules: UCG without # in a program is a warning (the
; manual's own example omits it: NC3047), under tool compensation an error (NC4103),
; DCG not after CLG a warning (NC4104).
N1 (UOT, 0, Z200)
N2 # (UCG, 1, X-100 X20, Y30 Y130)
N3 T1.1 M6
N4 G X-50 Y50
N5 (UCG, 2, X100 X150, Y50 Y250, Z)
N8  (CLG)
N9  (DCG)
N10 (DCG)
N11 G1 G41 X-40 Y60 F100
N12 # (UCG, 3, X0 X10, Y0 Y10)
N13 G40 X-30 M30
