; Process 2 of corpus-4.2.2-mutual-wait.nc (seed section 4.2.2, ПРОЦЕСС 2).
N230 G1 Y10 F1000
N231(SND,1)
N232(WAI,1)
N233 G1 Y20
M30
