; Drive faults (§2.8.15 L4630-4640: the M10 block of a G27/G28 profile must name every
; axis the profile moves, else «СБОЙ ПРИВОДА»; decision 47), ncc check: NC4055 "axis Z is
; clamped (M10/M12) and cannot move in a G27/G28 profile: drive fault", at the axis word.
; Expected: N2 Z under G27 (7:4); N3 Y under G28 (8:8); N8 B clamped by M12 (13:7).
; G29 (N9) has no such rule: N10 moves the clamped B without error.
N1 G1 X10 F100 M10
N2 Z-5
N3 G28 Y5
N4 G0 X0
N5 G27
N6 M11
N7 M12
N8 G1 B10
N9 G29
N10 B20
