diag-cli: a correct program for the usage errors of the command line (diag-cli.*.out)
%
N1 G01 X10 F100
N2 M30
