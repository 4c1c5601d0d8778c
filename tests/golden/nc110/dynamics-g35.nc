; G35 (§2.8.16, L4680-4700; decision 44's path events): the block's motion starts at the
; spindle's zero mark: a "path spindle_sync" event before the move; one-shot. G29: no G27
; profile rule.
; N2 spindle_sync, then the line to X10; N3 no G35: no event; N4 G35 on an arc: the event,
; then the arc (clockwise about X15 Y0 from X20 to X10, 180 deg).
N0 G29 S100 M3
N1 G0 X0 Y0
N2 G1 G35 X10 F100
N3 X20
N4 G2 G35 X10 Y0 I15 J0
