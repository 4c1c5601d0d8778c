threads-variable-undefined: G34/G35 need the pitch change per revolution, whose address the default profile does not name (NC4012, GOST 20999 §7.4)
%
N1 G90 G00 X10. Z5. S500 M03 (spindle turning)
N2 G34 Z-20. K1.5 (NC4012, increasing pitch)
N3 G00 Z5.
N4 G35 Z-20. K1.5 (NC4012, decreasing pitch)
N5 M02
