; PR100, process 2 of corpus-4.4.1-PR90.nc (seed section 4.4.1); elisions become a move.
N1 S400 M3 F300
N2 G1 X-10 Y-10
N140(REL)
