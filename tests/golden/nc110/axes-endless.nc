; An extended-range (endless) rotary axis B (seed §2.8.4, L2904-2958, Figs. 2.10-2.12;
; decision 48), profile motion-endless (3600 deg/min, B at 0 at the start).
; Under G90 the value 0..359.9999 is the target and its sign the way round; 0 goes the
; short way (decision 48, the manual's example 2); under G91 any signed increment.
; Positions show in 0..359.9999 (L2907: "always stays in the range 0 to 359.9999").
; N1 G91 B765 (example 3): +765 deg, shown B45, 12.75 s.
; Expected trace: B45, B90, B45, B90, B0, B90, B45, B90, B50; clock values as noted.
N1 G91 B765
E25 = TIM0
(DIS,E25)
; N2 to 90 (from 45, +45: 0.75 s), then example 1: B45 from 90 turns +315 (5.25 s), B45.
N2 G90 B90
E25 = TIM0
N3 B45
E26 = TIM0 - E25
(DIS,E26)
; Example 2: from 90, B0 turns -90 the short way (1.5 s), B0.
N4 B90
E25 = TIM0
N5 B0
E26 = TIM0 - E25
(DIS,E26)
; From 90, B-45: target 45 the negative way round, -45 (0.75 s), B45.
N6 B90
E25 = TIM0
N7 B-45
E26 = TIM0 - E25
(DIS,E26)
; From 45, B-90: target 90 the negative way round, -315 (5.25 s), B90.
E25 = TIM0
N8 B-90
E26 = TIM0 - E25
(DIS,E26)
; G91 B-400 from 90: -400 deg, shown B50 (6.666667 s).
N9 G91 B-400
