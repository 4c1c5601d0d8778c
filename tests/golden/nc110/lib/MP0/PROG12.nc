; PROG12, process 3 of corpus-4.4.2-PROG10.nc (seed 4.4.2, table 4.1); it ends without M30.
N1 S800 M3
N2 G0 X0 Y0
N34 G0 X10 Y10 Z5
