; Corpus copy of part2/2.8.1.7-G33-fig2.8c-cylindrical-taper-thread.nc (seed §2.8.1.7,
; L2584, Fig. 2.8 c): N35 a cylindrical thread of pitch 2.5 to Z-95, N36 (G33 modal, K
; repeated as the manual requires in every block) a taper thread to Z-100, diameter U52.
; Added: the spindle (S200, M03), the start Z5 U50 (profile motion-lathe: U diametral) and
; the clock after each thread.
; Derived (decision 42): N35 100 mm / 2.5 = 40 turns at 200 rpm = 12 s (the rapid before
; it max(5,50)/10000 min = 0.3 s: TIM0 12.3 s); N36 lead axis Z (5 against U 2/2 = 1),
; 2 turns = 0.6 s: TIM0 12.9 s.
N1 S200 M3
N2 G0 Z5 U50
N35 G33 Z-95 K2.5
E25 = TIM0
(DIS,E25)
N36 Z-100 U52 K2.5
E26 = TIM0
(DIS,E26)
