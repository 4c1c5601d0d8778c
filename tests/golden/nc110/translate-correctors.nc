; translate-correctors: T tool.corrector, applied at M06 (decision 11), into pp (its D
; word and length link &) and GOST 20999 (G43 H, in a block after the change); profile
; motion-tools: corrector 1 length 75 on Z, 10 length 50.5 on X (its [offsets] axis).
; Expected: after N2 the length X50.5; N4 none (corrector 0); N6 Z75, then a move.
N1 T1.10
N2 M06
N3 T6
N4 M06
N5 T1.1 M06
N6 G0 X20 Z10
