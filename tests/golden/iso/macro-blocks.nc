(blocks: ';' and the end of a line end a block, comments anywhere, lower case, free spacing, G#4 and M#5 from variables)
%
#1=1; #2=2; G01 X#1 Y#2 Z0 F100;
#3 = 3 (a comment inside the block) ; G01 Z#3
(lower case is read as upper case)
#4=1; g#4 x[#1+#2] y[sin[90]];
(spaces between tokens do not matter; none are needed either)
# 5 = 4 ;G 01 X # 5 Y [ # 5 * 2 ];
#6=5;IF[#6GT4]THEN#7=6;G01X#7
GOTO10;G01X99;N10G01Y#6;
(G and M numbers from variables)
#8=0;
G#8 X0 Y0 Z0;
#9=5;
M03 S1000;
M#9;
(N01 is block 1: GOTO 1 finds it)
GOTO 1;
G01 X98;
N01 G01 X1;
M30;
%
