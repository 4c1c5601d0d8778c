; PR98, process 2 of corpus-4.4.1-PR90.nc (seed section 4.4.1); elisions become moves.
N1 S500 M3 F800
N2 G1 X5 Y5
N3 G1 X15
N72(SND,1)
N73(REL)
