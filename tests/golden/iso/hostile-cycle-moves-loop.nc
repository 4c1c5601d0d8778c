(a loop of cycle blocks: --max-steps counts the moves a block makes beyond its first)
WHILE [1 EQ 1] DO1
G91 G83 X1 Y0 Z-3 R-1 Q1 L2 F100
END1
M30
