; G04 with TMR (§2.8.11 L4425, §2.10.1 L4935-4969; decision 45): the dwell comes after the
; block's motion and lasts TMR: seconds under G94 (at most 60), spindle revolutions under
; G95 (at most 30000). TMR is a global that persists; it takes a constant or an LR
; parameter. The dwell event shows seconds (docs/trace.md). G29: no G27 profile rule.
; N2 dwell 2 s. N3 the line (10 mm at F600 = 1 s) then the dwell 2 s: TIM0 5.
; N5 the limit under G94, 60 s: TIM0 65.
; N8 the limit under G95, 30000 revolutions at 600 rpm = 3000 s: TIM0 3065.
; N10 3 revolutions = 0.3 s: TIM0 3065.3.
; N11 TMR from E30 = 1.5, back under G94: 1.5 s: TIM0 3066.8.
N0 G29
N1 TMR=2
N2 G4
N3 G1 G4 X10 F600
E25 = TIM0
(DIS,E25)
N4 TMR=60
N5 G4
E25 = TIM0
(DIS,E25)
N6 G95 S600 M3
N7 TMR=30000
N8 G4
E25 = TIM0
(DIS,E25)
N9 TMR=3
N10 G4
E25 = TIM0
(DIS,E25)
E30 = 1.5
TMR=E30
N11 G94 G4
E25 = TIM0
(DIS,E25)
