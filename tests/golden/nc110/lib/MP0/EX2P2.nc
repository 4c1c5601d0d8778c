; Process 2 of corpus-4.2.1-ex2.nc (seed section 4.2.1, case 2, ПРОЦЕСС 2): it runs on.
N50 G1 Y10 F1000
N51 G1 Y20
M30
