; PROG93, process 3 of corpus-4.3-PROG91.nc (seed section 4.3, ПРОЦЕСС 3); elisions become moves.
N1(WAI,1)
N2 G1 Z10 F1000
N19 G1 X5 Y5
N20(WAI,SYVAR1=10)
N80(SND,1)
N81 G1 Z5
N93 G1 X0 Y0 Z0
N94(SND,1)
N95 (REL)
