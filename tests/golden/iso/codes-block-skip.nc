(block skip: a leading / skips the block when the switch is on; N and comments after it)
G01 X1 F100;
/G01 X2;
/N20 G01 Y2 (skipped too);
G01 X3;
M30;
