(a block's work is bounded: 9999 holes of 10,000 pecks each stop at a million moves, NC4095)
G90 G00 X0 Y0 Z10
G91 G83 X1 Y0 Z-100 R-5 Q0.01 L9999 F100
G80
M30
