(20 nested macros are allowed: a macro calling itself 19 times, counting the levels down from A20)
G90 G01 X0 Y0 Z0 F100;
G65 P9010 A20;
G65 P9010 A21;
M30;
O9010;
IF [#1 GT 1] THEN G65 P9010 A[#1-1];
IF [#1 EQ 1] THEN G01 X#1;
IF [#1 GE 20] THEN G01 Y#1;
M99;
