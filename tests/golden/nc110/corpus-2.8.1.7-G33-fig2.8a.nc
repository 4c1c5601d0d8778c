; Corpus copy of part2/2.8.1.7-G33-fig2.8a-cylindrical-thread.nc (seed §2.8.1.7, L2584-2640,
; Fig. 2.8 a): a cylindrical thread of constant pitch 2 along Z to Z-100.
; Added (the manual gives only N22): the spindle (S100 rpm, M03), the start X20 Z5 (the
; start appears only in the figure) and the clock. Decision 42: K the pitch, the thread
; needs a spindle encoder (the default profile has one; see the .noencoder.out variant).
; Derived: N2 rapid max(20,5)/10000 min = 0.12 s; N22 105 mm / 2 = 52.5 turns at 100 rpm
; = 31.5 s; TIM0 = 31.62 s.
N1 S100 M3
N2 G0 X20 Z5
N22 G33 Z-100 K2
; added: the clock
E25 = TIM0
(DIS,E25)
