(IF THEN M99 returns early; O1000's last block is not M99, so E-28 'does not end with M99' applies; a vacant G65 argument stays vacant)
G90 G01 X0 Y0 Z0 F100;
#1=0;
M98 P1000;
G01 Y1;
#1=5;
M98 P1000;
G01 Y2;
G65 P1001 A#5 B2;
M30;
O1000;
IF [#1 GT 2] THEN M99;
G01 X1;
O1001;
IF [#1 EQ #0] THEN G01 Z1;
G01 Z#2;
M99;
