(program structure errors: an O header before M30, a program defined twice, a header that shares its block, O with 5 digits)
G01 X1 F100;
M98 P1000;
O1000;
G01 X2;
M99;
M30;
O1001;
G01 X3;
M99;
O1001;
G01 X4;
M99;
O1002 G01 X5;
M99;
O12345;
M99;
