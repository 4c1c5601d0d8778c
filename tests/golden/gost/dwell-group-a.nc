dwell-group-a: with g04_mode = group_a, G04 is a member of the motion group a and stays in force (GOST 20999 Table 4 note 2)
%
N1 G90 G01 X10. F100. (G01 in force)
N2 G04 P2. (dwell 2 seconds, group a now holds G04)
N3 P1.5 (G04 still in force, a block with P alone dwells)
N4 G01 X20. (G01 replaces G04)
N5 G04 P1. (group a holds G04 again)
N6 X30. (NC4002, axis words while group a holds G04)
N7 M02
