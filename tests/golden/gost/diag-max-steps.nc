diag-max-steps: four blocks; --max-steps 2 stops before the third (NC4021)
%
N1 G01 X10 F100 (block 1)
N2 X20 (block 2)
N3 X30 (block 3 - the limit is reached here)
N4 M30
