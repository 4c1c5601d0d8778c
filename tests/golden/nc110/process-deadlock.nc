; Two processes that wait for each other (decision 63): process 1 waits for a restart from process 2
; (lib/MP0/DEADL2), which waits for one from process 1. No process can go on: the run stops with
; NC4090 at the first, and a note at each; ncc check finds it too (process-deadlock.check).
N1 G1 X10 F1000
N2 (WAI,2)
N3 (SND,2)
M30
