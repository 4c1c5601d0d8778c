(a macro calling itself with a counter argument until a condition stops it; each level keeps its own #1)
G90 G01 X0 Y0 Z0 F100;
G65 P9007 A4;
G01 X0 Y0 Z0;
(factorial of 5 by recursion, returned in the common #500)
G65 P9008 A5;
G01 X#500;
M30;
O9007;
G01 X#1 Y0;
IF [#1 GT 1] THEN G65 P9007 A[#1-1];
(after the inner calls return, #1 is this level's own value again)
G01 Y#1;
M99;
O9008;
IF [#1 LE 1] GOTO 10;
G65 P9008 A[#1-1];
#500=#500*#1;
M99;
N10 #500=1;
M99;
