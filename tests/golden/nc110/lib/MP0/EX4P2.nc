; Process 2 of corpus-4.2.1-ex4.nc (seed section 4.2.1, case 4, ПРОЦЕСС 2).
N120 G1 Y1 F1000
N121(WAI,SYVAR2=31)
N122 G1 Y10
N123 G1 Y20
M30
