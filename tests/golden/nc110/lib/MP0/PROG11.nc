; PROG11, process 2 of corpus-4.4.2-PROG10.nc (seed 4.4.2, table 4.1): a drilling cycle.
N1 S400 M3
N2 G81 R2 Z-50 F500
N3 X-20 Y10
N40 G80 X0 Y0 Z0 M30
