tape-programs: three programs on one medium run in order; M02 resets, M30 ends the information (GOST 20999 §1.8, §1.9, §8; decisions 1, 4, 21)
%%0001 (tape start marker, then program 0001)
N1 G91 G18 G00 X10. Z5. S500 M03 M08 (incremental, ZX plane, spindle and coolant on)
N2 G01 X1. F200 (a feed move to X11)
N3 M02 (spindle and coolant stop, the NC returns to its power-on state)
leader text between two programs is ignored again
%0002 (program 0002)
N1 G00 X1. (G90 again - X1, not X12; the position is kept, Z stays 5)
N2 G02 X3. Y0 I1. J0 F50 (G17 again - a half circle in XY around X2 Y0)
N3 M02
% (a program without number)
N1 G00 X4.
N2 M30 (end of information)
%0004 (not read - NC1007 once, for this line)
N1 X9. (nor this)
