; The power-on feed and spindle modes (decision 38; Table 2.2, seed L1600-1673; §2.7.5,
; §2.7.6, §2.10.1). The default profile powers on with G94 G97 (mm/min, rpm); the
; .g95.out variant runs with profile motion-g95: Table 2.2's printed G95 G96 (mm/rev,
; cutting speed in m/min). The same program, two clocks (decision 50).
; Default: N2 rapid 50/10000 min = 0.3 s; N3 10 mm at F2 mm/min = 300 s (TIM0 300.3);
;   N5 G04 dwells TMR = 2 s (TIM0 302.3).
; G95 G96: S100 m/min at the diameter 2*|X| = 100 (decision 49): 318.3099 rpm; N3 at F2
;   mm/rev = 636.6198 mm/min: 0.942478 s (TIM0 1.242478); N5 at X60 (diameter 120,
;   265.2582 rpm): TMR = 2 revolutions = 0.452389 s (TIM0 1.694867).
N1 S100 M3
N2 G0 X50
N3 G1 X60 F2
E25 = TIM0
(DIS,E25)
N4 TMR=2
N5 G4
E25 = TIM0
(DIS,E25)
