end-stops: M00 stops after its block; M01 only with the optional-stop switch (--optional-stop); a run records the stop and goes on (GOST 20999 Table 8, ncc decision 21)
%
N1 G00 X1. S500 M03 M08
N2 X2. M00 (program stop after the move; spindle and coolant are not recorded as changed)
N3 X3. M01 (optional stop after the move)
N4 M01 (a block with M01 alone)
N5 X4. (the run goes on as if the operator had resumed)
N6 M30
