; Helices (§2.8.1.6, L2499-2563; decision 41): K is the pitch (travel per turn); the
; number of turns is the one K and the travel agree on, within the arc tolerance 0.01 mm;
; without K the third axis moves in proportion to the angle. "The length is n*K. If n is
; an integer, program a full circle; if not, the arc 360*frac(n): 2.7K gives 252 deg"
; (L2555-2560). G29: no G27 profile rule.
; N1 full circle from X10 Y0, Z-6 at K2: 3 turns, sweep 1080; path sqrt((10*6pi)^2+6^2)
;   = 188.5910 mm at F100 = 113.1546 s, after the 0.06 s rapid: TIM0 113.2146.
; N3 2.7 turns at K2 (Z-5.4): the programmed arc is 252 deg, its end X-3.0902 Y-9.5106
;   (cos, sin of 252 deg, 4 decimals: 251.99998 deg): sweep 720 + 252 = 971.9999.
; N5 2.75 turns (Z-5.5): the 270 deg arc to X0 Y-10 plus 2 turns: sweep 990.
; N7 no K: a 90 deg arc with Z-3 moving in proportion: sweep 90.
; N9 Z-5.51 with K2 and the 270 deg arc: 2.755 turns, 0.01 mm from 2.75 turns: accepted,
;   sweep 990.
; N11 clockwise 90 deg plus one turn rising Z5 at K4 (1.25 turns): sweep 450.
N0 G29 G0 X10 Y0 Z0
N1 G3 X10 Y0 Z-6 I0 J0 K2 F100
E25 = TIM0
(DIS,E25)
N2 G0 Z0
N3 G3 X-3.0902 Y-9.5106 Z-5.4 I0 J0 K2
N4 G0 X10 Y0 Z0
N5 G3 X0 Y-10 Z-5.5 I0 J0 K2
N6 G0 X10 Y0 Z0
N7 G3 X0 Y10 Z-3 I0 J0
N8 G0 X10 Y0 Z0
N9 G3 X0 Y-10 Z-5.51 I0 J0 K2
N10 G0 X10 Y0 Z0
N11 G2 X0 Y-10 Z5 I0 J0 K4
