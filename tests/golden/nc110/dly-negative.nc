; dly-negative: a negative time from an LR parameter is an error when DLY runs
; (codes digest §4 [P]: "< 0"): NC4065 at the operand.
E30=-1
N7 (DLY,E30)
M30
