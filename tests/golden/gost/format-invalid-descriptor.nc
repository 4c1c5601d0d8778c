format-invalid-descriptor: any program; the profile's descriptor does not load (NC6004, exit 2)
%
N1 G00 X1
N2 M02
