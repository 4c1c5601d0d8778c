diag-files: a correct program for the file and dialect errors (NC6001, NC6002, NC6007; diag-files.*.out)
%
N1 G01 X10 F100
N2 M30
