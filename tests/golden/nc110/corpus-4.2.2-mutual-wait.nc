; source: ../shared/corpus/nc110/part5/4.2.2-mutual-wait-process{1,2,3}.nc (seed section 4.2.2)
; expect: the three processes wait for each other and pass blocks N112 (process 1), N233 (process 2)
; and N333 (process 3) together.
; Changes: this is process 1; processes 2 and 3 are lib/MP0/MUTW2 and lib/MP0/MUTW3, started with the
; run (--process, as the keyboard's SPG selects them). The dotted elisions become one move before the
; waits and one after (N107, N112 here; N230, N233 and N330, N333 there), each process on its own axis;
; M30 ends each. Process 3's SND comes while process 1 still waits for process 2: it waits until
; process 1 waits for it (decision 63), and is neither lost nor an error (seed 4.2.2).
N107 G1 X10 F1000
N108(WAI,2)
N109(WAI,3)
N110(SND,2)
N111(SND,3)
N112 G1 X20
M30
