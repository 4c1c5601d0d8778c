; G34 is G33 printed alike (§2.8.1.7; decision 42): K the pitch, I the change, R the
; start angle. The same thread as corpus-2.8.1.7-G33-fig2.9a under G34, and G34 modal in
; the next block. G29: no G27 profile rule; S100 rpm.
; N2 from Z0 to Z-50, K4 I1: 4 ln(4.125) = 5.668264 turns = 3.400959 s.
; N3 modal G34 with its own K (every block needs one), from Z-50 to Z-60 at K5 R180:
;   2 turns, 1.2 s: TIM0 4.600959 (4.600958 as an RE value).
N0 G29 S100 M3
N1 G0 Z0
N2 G34 Z-50 K4 I1
E25 = TIM0
(DIS,E25)
N3 Z-60 K5 R180
E25 = TIM0
(DIS,E25)
