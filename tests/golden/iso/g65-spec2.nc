(G65 argument specification II: A B C, then up to 10 sets of I J K give #4..#33; In is #[3n+1], Jn #[3n+2], Kn #[3n+3])
G90 G01 X0 Y0 Z0 F100;
(the seed's example without L: #4=68.4 #5=-13 #6=4 #7=-18.5 #8=-9 #9=50.2 #10=19.2 #11=-1)
G65 P9003 I68.4 J-13 K4 I-18.5 J-9 K50.2 I19.2 J-1;
(a set may leave letters out: I J then J starts the next set, K then I too)
G65 P9003 A1 I4 J5 J8 K9 I10 K12;
(all ten sets)
G65 P9003 I4 J5 K6 I7 J8 K9 I10 J11 K12 I13 J14 K15 I16 J17 K18 I19 J20 K21 I22 J23 K24 I25 J26 K27 I28 J29 K30 I31 J32 K33;
M30;
O9003;
G01 X#1 Y#2 Z#3;
G01 X#4 Y#5 Z#6;
G01 X#7 Y#8 Z#9;
G01 X#10 Y#11 Z#12;
G01 X#13 Y#14 Z#15;
G01 X#16 Y#17 Z#18;
G01 X#19 Y#20 Z#21;
G01 X#22 Y#23 Z#24;
G01 X#25 Y#26 Z#27;
G01 X#28 Y#29 Z#30;
G01 X#31 Y#32 Z#33;
G01 X0 Y0 Z0;
M99;
