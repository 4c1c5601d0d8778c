; Constant cutting speed G96 (§2.7.6, decision 49) with feed per revolution G95, profile
; motion-maxrpm (max_rpm 1000). S is the cutting speed in m/min at the diameter twice X
; (no diametral axis here), capped at max_rpm, set at the start of each block; it sets the
; rpm of the G95 feeds and so the clock (decision 50). G29: no G27 profile rule.
; N2 rapid 50/10000 min = 0.3 s. N3 at X50: diameter 100, 1000*157.08/(pi*100) =
;   500.0012 rpm; 10 mm at 0.2 mm/rev = 5.999986 s: TIM0 6.299986.
; N4 rapid 0.24 s. N5 at X10: 2500 rpm capped to 1000: 10 mm at 200 mm/min = 3 s: TIM0
;   9.539986.
; N6 rapid 0.06 s. N7 at X0 (diameter 0): the cap, 1000 rpm: 3 s: TIM0 12.59999.
; N8 G70 (inch): S in ft/min; N9 rapid to X2 in = 50.8 mm (0.3048 s); N10 at diameter 4 in:
;   12*500/(pi*4) = 477.4648 rpm, 1 in at 0.01 in/rev = 4*pi s = 12.56637 s: TIM0 25.47116.
N0 G29
N1 G95 G96 S157.08 M3
N2 G0 X50
N3 G1 Z-10 F0.2
E25 = TIM0
(DIS,E25)
N4 G0 X10
N5 G1 Z-20
E25 = TIM0
(DIS,E25)
N6 G0 X0
N7 G1 Z-30
E25 = TIM0
(DIS,E25)
N8 G70 S500
N9 G0 X2 Z0
N10 G1 Z-1 F0.01
E25 = TIM0
(DIS,E25)
