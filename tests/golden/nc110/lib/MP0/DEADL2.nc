; Process 2 of process-deadlock.nc: it waits for process 1 before it restarts it.
N10 G1 Y10 F1000
N11 (WAI,1)
N12 (SND,1)
M30
