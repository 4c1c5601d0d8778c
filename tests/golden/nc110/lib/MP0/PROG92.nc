; PROG92, process 2 of corpus-4.3-PROG91.nc (seed section 4.3, ПРОЦЕСС 2); elisions become moves.
N1 G1 Y10 F1000
N2 G1 X5 Y5 Z-5
N3 G2 X10 Y10 I10 J5
N15 G1 X0 Y0
N16(WAI,1)
G1 X5
N40(WAI,SA10=1)
N85(SND,1)
N86 G1 Y15
N98 G1 X0 Y0 Z0
N99(SND,1)
N100(REL)
