(G65 argument specification I: A B C I J K D E F H M Q R S T U V W X Y Z give #1 #2 #3 #4 #5 #6 #7 #8 #9 #11 #13 #17 #18 #19 #20 #21 #22 #23 #24 #25 #26)
G90 G01 X0 Y0 Z0 F100;
G65 P9001 A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25 Z26;
(word order does not matter; the letters not given stay vacant; M30 here is #13=30, not the end of the program)
G65 P9001 Z-26 A-1 M30;
M30;
O9001;
G01 X#1 Y#2 Z#3;
G01 X#4 Y#5 Z#6;
G01 X#7 Y#8 Z#9;
G01 X#10 Y#11 Z#12;
G01 X#13 Y#14 Z#15;
G01 X#16 Y#17 Z#18;
G01 X#19 Y#20 Z#21;
G01 X#22 Y#23 Z#24;
G01 X#25 Y#26 Z0;
G01 X0 Y0 Z0;
M99;
