dwell-errors: G04 needs its time (NC4016) and takes no axis words (NC4015), P without G04 has no effect (NC4025), GOST 20999 Table 5
%
N1 G90 G01 X10. F100. (G01 in force)
N2 G04 (NC4016, no time in P)
N3 G04 X5. P1. (NC4015, a dwell with axis motion)
N4 P3. (NC4025, P without G04)
N5 M02
