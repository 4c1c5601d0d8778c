m-stop-last: M00/M01 act after every other function of their block (docs/dialects/gost.md block order; GOST 20999 Table 8 M00 - stop after the commands of the block)
%
N1 G00 S100 M03 M07
N2 X1. M00 M09 (the coolant goes off, then the program stops)
N3 X2. M01 M05 (the spindle stops, then the optional stop)
N4 M30
