; dly-runtime: a time from an LR parameter is checked when DLY runs: 0..32 s
; (§2.13.6.2 L9625-9629; codes digest §4: "R: E value > 32 or < 0"). NC4065 at
; the operand; the first DLY runs.
E30=32
(DLY,E30)
E30=32.5
N7 (DLY,E30)
(DIS,"NOT REACHED")
M30
