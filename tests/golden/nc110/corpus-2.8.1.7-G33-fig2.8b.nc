; Corpus copy of part2/2.8.1.7-G33-fig2.8b-taper-thread.nc (seed §2.8.1.7, L2608, L2660,
; Fig. 2.8 b): a taper thread of pitch 3; U is a diametral axis (profile motion-lathe).
; Corrected: the block prints "X-80" (L2660, L14046); the figure labels "Z-80" and "U40"
; (L14057-14058), so the copy reads Z-80 (nc110-corpus.md §H).
; Added: the spindle (S100, M03), the start Z0 U60 (a diameter of 60) and the clock.
; Derived (decision 42): the lead axis is the longest travel, a diametral axis counting
; half: Z 80 against U 20/2 = 10, so Z; 80/3 = 26.667 turns at 100 rpm = 16 s; the rapid
; max(0,60)/10000 min = 0.36 s; TIM0 = 16.36 s.
N1 S100 M3
N2 G0 Z0 U60
N22 G33 Z-80 U40 K3
; added: the clock
E25 = TIM0
(DIS,E25)
