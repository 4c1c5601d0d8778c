; Process 2 of corpus-4.2.1-ex3.nc (seed section 4.2.1, case 3, ПРОЦЕСС 2): it runs on.
N200 G1 Y10 F1000
N201 G1 Y20
M30
