(M98 shares the locals #1-#33 with its caller, G65 does not; subprograms nest: O1000 calls O1001 calls O1002)
G90 G01 X0 Y0 Z0 F100;
#1=1;
#2=2;
M98 P1000;
(O1000 changed #1 and O1001 changed #2: the changes are seen here)
G01 X#1 Y#2 Z#3;
(the same subprogram called as a macro: its changes are lost)
#1=1;
G65 P1000;
G01 X#1 Y#2 Z#3;
M30;
O1000;
#1=#1+10;
M98 P1001;
G01 Z1;
M99;
O1001;
#2=#2+20;
M98 P1002;
G01 Z2;
M99;
O1002;
#3=30;
G01 X#1 Y#2 Z#3;
M99;
