%12 "block numbers in any order: unique in the file, a jump finds each"
N30 G90 G01 X1 F100
N10 X2
N20 G73 L10 Q1 "back to N10, written after N30: N10, N20 run twice"
N40 X3
N10 Y1 "N10 again"
N30 Y2 "N30 again"
N50 M30
