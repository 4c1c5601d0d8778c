; G33 along the longest travel (decision 42; §2.8.1.7 L2608 "U is a diametral axis"),
; profile motion-lathe (U diametral). K is the pitch along the lead axis: the longest
; travel, a diametral axis counting half. G29: no G27 profile rule. S100 rpm.
; N3 X30 Z-10: lead X (30 > 10), 15 turns = 9 s: TIM0 9.
; N5 U60 Z-10: U counts 60/2 = 30 > 10, 15 turns = 9 s; after the 0.18 s rapid: 18.18.
; N7 U10 Z-10: U counts 5 < 10, lead Z, 5 turns = 3 s; after the 0.36 s rapid: 21.54.
; N9 the start angle R from an LR parameter: E30 = 90, phase 90; the pitch from an LR
;   parameter E31 = 2.5.
N0 G29
N1 S100 M3
N3 G33 X30 Z-10 K2
E25 = TIM0
(DIS,E25)
N4 G0 X0 Z0
N5 G33 U60 Z-10 K2
E25 = TIM0
(DIS,E25)
N6 G0 U0 Z0
N7 G33 U10 Z-10 K2
E25 = TIM0
(DIS,E25)
N8 G0 U0 Z0
E30 = 90
E31 = 2.5
N9 G33 Z-20 KE31 RE30
