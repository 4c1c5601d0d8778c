; Clamps (§2.8.15 L4600-4665, Table 2.3; decision 47): M10 clamps the axes its block does
; not name, M12 the rotary axes it does not name, M11 unclamps all; all three act at the
; start of the block (Table 2.3). Under G27/G28 only a feed move of a clamped axis is a
; drive fault (dynamics-clamps-errors); this run has none.
; N2 clamp on before the line; X and Y are named (Y0 does not move), Z, A, B, C... clamped.
; N3, N4 move Y and X in the profile: legal. N5 a rapid of the clamped Z: legal (the
; rule is for feed moves), and it ends the profile. N6 M11: clamp off, rotary_off.
; N7 Z moves again. N9 M12 (after the rapid N8): clamp rotary_on; N10 a feed of X: legal.
; N12 M11 unclamps.
N1 G0 X0 Y0
N2 G1 X10 Y0 M10 F100
N3 Y10
N4 X0
N5 G0 Z5
N6 M11
N7 G1 Z0
N8 G0 X5
N9 M12
N10 G1 X10
N11 G0 X0
N12 M11
