; The run's clock TIM0 after known moves (decision 50; §2.10.6, §2.7.5, §2.8.13), profile
; motion-rapids: rapid X 10000, Y 5000, Z 2000 mm/min. TIM0 is read into the RE parameter
; E25 (7 significant digits).
; N1 rapid: the slowest axis, max(100/10000, 100/5000, 10/2000) min = 1.2 s.
; N2 rapid Z 30/2000 min = 0.9 s: TIM0 2.1.
N1 G0 X100 Y100 Z10
N2 Z-20
E25 = TIM0
(DIS,E25)
; N3 feed 141.4214 mm at F1000 mm/min = 8.485281 s: TIM0 10.58528.
N3 G1 X0 Y0 F1000
E25 = TIM0
(DIS,E25)
; N4 a full circle about X50 Y50 (I J absolute; the end X0 Y0 is the start, decision 39):
; 2*pi*70.71068 = 444.2883 mm at F1000 = 26.6573 s: TIM0 37.24258.
N4 G2 X0 Y0 I50 J50
E25 = TIM0
(DIS,E25)
; N5 the time word t: 4 s whatever F (its block only): TIM0 41.24258.
N5 G1 X10 t4
; N7 G04 dwells TMR = 1.5 s: TIM0 42.74258.
N6 TMR=1.5
N7 G4
E25 = TIM0
(DIS,E25)
; N8 inverse time: F6 = the block in 1/6 min = 10 s: TIM0 52.74258.
N8 G93 G1 X20 F6
E25 = TIM0
(DIS,E25)
; N9 back to G94: F must be programmed again; 20 mm at F600 = 2 s: TIM0 54.74258.
N9 G94 G1 X40 F600
E25 = TIM0
(DIS,E25)
