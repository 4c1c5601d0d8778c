Run-time errors of the formulas: division by zero, and a result beyond +-69999.999.
%8
N10 R1 10 R2 0
N20 G29 R1 R2
N30 M30
