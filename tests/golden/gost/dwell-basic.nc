dwell-basic: G04 with the time in P in seconds acts in its block only, the motion mode stays (GOST 20999 Table 4 note 2, Table 5, ncc decision 15)
%
N1 G90 G01 X10. F100. (G01 in force)
N2 G04 P2.5 (dwell 2.5 seconds)
N3 X20. (G01 still in force after the dwell)
N4 G00 X0
N5 G04 P10 (P10 without a point is the integer 10 seconds)
N6 X5. (G00 still in force)
N7 G04 P0.001 (the smallest dwell of format P+053)
N8 M02
