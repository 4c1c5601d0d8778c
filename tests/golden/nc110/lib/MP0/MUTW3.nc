; Process 3 of corpus-4.2.2-mutual-wait.nc (seed section 4.2.2, ПРОЦЕСС 3).
N330 G1 Z10 F1000
N331(SND,1)
N332(WAI,1)
N333 G1 Z20
M30
