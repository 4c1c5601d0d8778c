; words-bare-errors: only G, the axes, I, J, K and R may stand without a value
; (§2.4.3; decision 4); any other address needs one (NC2013).
; the manual's L8714 with its M elided: column 9
N14 X Y M M30
G1 X1 F
S
T
H
G0 X1 F100 t
