; Corpus copy of part2/2.8.1.7-G33-fig2.9a-increasing-pitch.nc (seed §2.8.1.7, L2584-2640,
; Fig. 2.9 a): initial pitch 4, pitch change I+1 (increasing), to Z-50.
; Added: the spindle (S100, M03), the start Z0 and the clock.
; Derived (decision 42, p(s) = K + I*s/K): end pitch 4 + 50/4 = 16.5; turns
; n = (K/I) ln(1 + I*L/K^2) = 4 ln(4.125) = 5.668264 at 100 rpm = 3.400959 s.
N1 S100 M3
N2 G0 Z0
N24 G33 Z-50 K4 I1
; added: the clock
E25 = TIM0
(DIS,E25)
