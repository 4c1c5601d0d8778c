(Fanuc system variables, decision 48: modal codes #4001-#4017, modal words #4107-#4120, positions #5001-#5043, work offsets #5221-#5323 read and written, the run clock #3001, alarm #3000)
G17 G90 G21 G54 G00 X10 Y20 Z5;
#1=#4001; #2=#4003; #3=#4014; #4=#5041; #5=#5042; #6=#5021;
G01 X#1 Y#2 Z#3 F100;
#7=#4109;
G91 G01 X#7 Y#4006;
#5221=10;
G90 G00 X0 Y0;
#100=#5221;
#3001=0;
G04 P2.;
#101=#3001;
G01 X#100 Y#101 Z#4002;
#3000=12;
