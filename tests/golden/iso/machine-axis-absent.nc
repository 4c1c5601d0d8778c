(decision 63: a fourth-axis program on a machine without A is one error naming the axis and the machine, not a warning per block and every hole in one place; --machine haas has A)
G90 G00 X0 Y0 Z10;
G81 X10 Y0 Z-5 R2 F100;
A90;
A180;
G80;
M30;
