(G98 after G99 holes, spec 8.21 8.23: G98 returns to the initial point, the position before the cycle started, and under G91 R is measured from it; decision 18 takes the level where the tool stands at the block start, docs' difference table the Z where the cycle's sequence started; EXPECTED line 4 to return to Z50 and line 7 to drill R5 to Z-7 as line 6 and return to Z20; ncc uses Z2 and Z5, and the G91 hole of line 7 goes 15 mm deeper, to Z-22)
G90 G00 X0 Y0 Z50;
G99 G81 X10 Y10 Z-5 R2 F100;
G98 X20;
G80 G00 Z20;
G91 G99 G81 X10 Z-12 R-15;
G98 Y10;
G90 G80;
M30;
