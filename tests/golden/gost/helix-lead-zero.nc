helix-lead-zero: a lead of 0 fits no travel (NC4007, GOST 20999 §4.3.4)
%
N1 G90 G17 G00 X10. Y0 Z0 F100.
N2 G03 X-10. Y0 Z5. I-10. J0 K0 (NC4007)
N3 M02
