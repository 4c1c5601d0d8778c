format-lenient-nondim: lenient mode also reads a non-dimension word with too few digits (NC2008)
%
N5 G00 X1. (N5 - warning)
N005 X2.
N010 M02
