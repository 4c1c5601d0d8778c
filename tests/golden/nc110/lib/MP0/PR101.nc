; PR101, process 3 of corpus-4.4.1-PR90.nc (seed section 4.4.1); elisions become a move.
N1 S2000 M3 F500
N2 G1 Z-20
N138(REL)
