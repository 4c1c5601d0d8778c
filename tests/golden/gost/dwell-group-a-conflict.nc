dwell-group-a-conflict: G04 with a motion code in one block is a group conflict when G04 is in group a (NC3002), allowed when G04 acts in its block only (GOST 20999 Table 4 note 2, §2.5)
%
N1 G90 G00 X10. F100. (G00 in force)
N2 G01 G04 P1. (group_a, NC3002, block_only, dwell 1 second)
N3 G01 X20. (a feed move in both modes)
N4 M02
