(WHILE [..] DO1 .. END1 and nesting DO1/DO2/DO3; a loop of no iterations; an index used again after its END)
G01 X0 Y0 Z0 F100;
(the seed's example, shortened: #1 from 300 down to 200 in steps of 50, two squares)
N01 #1=300;
N02 #2=200;
N03 WHILE [#1 GT #2] DO1;
N04 #1=#1-50
N05 G91 X10;
N06 Y-10;
N07 X-10;
N08 Y10;
N09 END1;
G90;
G01 X#1;
(three levels: 2 x 2 x 2 = 8 moves of the innermost body)
#10=0;
#1=0;
WHILE [#1 LT 2] DO1;
#1=#1+1;
#2=0;
WHILE [#2 LT 2] DO2;
#2=#2+1;
#3=0;
WHILE [#3 LT 2] DO3;
#3=#3+1;
#10=#10+1;
G01 X#1 Y#2 Z#3;
END3;
END2;
END1;
G01 X#10 Y0 Z0;
(a false condition at the start: the body never runs)
WHILE [#10 LT 0] DO1;
G01 X99;
END1;
(DO2 first and DO1 inside: the order of the indices is free, nesting is what counts)
#1=0;
WHILE [#1 LT 2] DO2;
#1=#1+1;
#2=0;
WHILE [#2 LT 1] DO1;
#2=#2+1;
G01 Y[#1*10+#2];
END1;
END2;
M30;
