; Process 2 of process-sync.nc: it waits for each of process 1's writes and shows the time.
N10 (WAI,SYVAR1=1)
N11 (DIS,"SYVAR1 ",TIM0)
N12 (WAI,SYVAR2=1)
N13 (DIS,"SYVAR2 ",TIM0)
N14 (WAI,SK20=1)
N15 (DIS,"SK20 ",TIM0)
N16 (WAI,SK21=1)
N17 (DIS,"SK21 ",TIM0)
M30
