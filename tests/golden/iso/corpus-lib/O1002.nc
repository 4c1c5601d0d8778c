O1002 (the seed's G65 example 2 calls it: its arguments #4..#12, three at a time, as moves)
G90 G01 X#4 Y#5 Z#6 F100;
X#7 Y#8 Z#9;
X#10 Y#11 Z#12;
M99;
