; Process 2 of corpus-4.2.1-ex1.nc (seed section 4.2.1, case 1, ПРОЦЕСС 2).
N105 G1 Y5 F1000
N106(WAI,1)
N107 G1 Y10
M30
