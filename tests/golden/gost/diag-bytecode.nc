diag-bytecode: the program behind the diag-bc-*.bin bytecode files (compiled, then damaged by diag-bc-make.py)
%
N1 G01 X0 Y10 F100
N2 M30
