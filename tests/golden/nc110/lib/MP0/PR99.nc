; PR99, process 3 of corpus-4.4.1-PR90.nc (seed section 4.4.1); elisions become moves.
N1(WAI,1)
N2 S1000 M3 F600
N3 G1 Z-5
N68 G1 X0 Y0 Z0
N69(SND,1)
N70(REL)
