; Threading needs a spindle encoder (§2.8.1.7 L2598; decision 42), profile
; motion-noencoder (machine.spindle_encoder = false). G34 is G33 printed alike
; (decision 42). ncc check. G29: no G27 profile rule.
; Expected: NC4067 "G33 needs a spindle encoder, which this machine lacks
; (machine.spindle_encoder)" (8:1) and the same for G34 (10:1).
N0 G29 S100 M3
N1 G0 Z0
N2 G33 Z-50 K2
N3 G0 Z0
N4 G34 Z-50 K2 I0.5
