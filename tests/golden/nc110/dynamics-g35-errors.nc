; G35 errors (§2.8.16, L4689: not with G00; decision 44), ncc check: NC4054 "G35 cannot
; start the motion at the spindle's zero mark: <why>", at the block.
; Expected: N1 G35 with G00 the active motion: "G00 is the active motion" (8:1);
; N3 the spindle stopped: "the spindle is not turning" (10:1); N5 a block that moves no
; axis: "its block moves no axis" (12:1). (G00 and G35 in one block is the static NC3013,
; Table 2.4.)
N0 G29 G0 X0 Y0
N1 G35 X10
N2 G1 X0 F100
N3 G35 X10
N4 S100 M3
N5 G35
