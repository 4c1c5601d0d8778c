; G96 with a diametral axis (decision 49), profile motion-lathe (U diametral): the
; cutting speed is taken at the diameter U as written, not at twice X.
; N2 rapid max(30,100)/10000 min = 0.6 s; N3 at U100 (X30 does not count): 1000*157.08/
; (pi*100) = 500.0012 rpm, 10 mm at 0.2 mm/rev = 5.999986 s: TIM0 6.599986.
N0 G29
N1 G95 G96 S157.08 M3
N2 G0 X30 U100
N3 G1 Z-10 F0.2
E25 = TIM0
(DIS,E25)
