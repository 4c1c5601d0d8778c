(WORDDEC: a constant of at most 9 decimals whose digits fit 32 bits; WORD: -0 and the others, from the table)
G17 G21 G90 G94 F100
G01 X12.345 Y-0.5 Z0.123456789
G01 X0.1234567891 Y-0 Z3000000000
G01 X-2147483.647 Y2147483647 Z-2147483648
M30
