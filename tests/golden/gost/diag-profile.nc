diag-profile: a correct program, run with broken machine profiles (NC6001, NC6003-NC6006; diag-profile.*.out)
%
N1 G01 X10 F100
N2 M30
