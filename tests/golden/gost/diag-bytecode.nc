diag-bytecode: the program behind the diag-bc-*.bin bytecode files (compiled, then damaged)
%
N1 G01 X10 F100
N2 M30
