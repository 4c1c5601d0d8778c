(M98 calls share the nesting limit of 20 with G65 macros: a subprogram calling itself stops at the 21st call)
G90 G01 X0 Y0 Z0 F100;
#100=0;
M98 P1000;
M30;
O1000;
#100=#100+1;
IF [#100 GT 18] THEN G01 X#100;
M98 P1000;
M99;
