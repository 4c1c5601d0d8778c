O1001 (the seed's G65 example 1 calls it: its arguments #1, #2 and #17 as a move)
G91 G01 X#1 Y#2 Z#17 F100;
M99;
