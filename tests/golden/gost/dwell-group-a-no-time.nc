dwell-group-a-no-time: with G04 in the motion group (g04_mode group_a), a G04 block still needs its time (NC4016, GOST 20999 Table 5)
%
N1 G90 G01 X1. F100.
N2 G04 (NC4016, G04 without its time)
N3 G01 X2.
N4 M02
