helix-no-lead: a helix without its third interpolation parameter, the axis moves in proportion to the angle, warning NC4008 (GOST 20999 §4.3.4)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0 0)
N2 G03 X-10. Y0 Z5. I-10. J0 F100. (NC4008, no K, half circle, Z to 5)
N3 G18 G02 X10. Y4. I10. K0 (NC4008, no J in G18, Z5 X-10 to Z5 X10 about Z5 X0, Y to 4)
N4 G17 G03 X-10. I-10. K1. (no Z word, not a helix, K has no effect, NC4025, half circle about X0 Y4)
N5 M02
