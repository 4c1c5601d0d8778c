(G17 G18 G19, spec 8.5: the plane picks the arc's pair of centre words, G17 I J, G18 I K, G19 J K, and a word of the other axis is warned as unused NC4025; a linear move is the same in any plane; M30 restores G17)
G90 G00 X0 Y0 Z0;
G17 G02 X10 Y0 Z0 I5 J0 K5 F100;
G18 G02 X20 Y0 Z0 I5 J5 K0;
G19 G02 X20 Y10 Z0 I5 J5 K0;
G18 G01 X30;
M30;
