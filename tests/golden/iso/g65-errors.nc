(G65 errors: D and a second I set both give #7, an 11th I set, a letter given twice, no P, P not a whole number, L above 999, a G code in the call block)
G65 P9004 D7 I4 J5 K6 I7;
G65 P9004 A1 A2;
G65 P9004 I1 I2 I3 I4 I5 I6 I7 I8 I9 I10 I11;
G65 A1 B2;
G65 P9004.5 A1;
G65 P12345 A1;
G65 P9004 L1000 A1;
G01 G65 P9004 A1;
G65 P9004 A1 M98 P1000;
M30;
O9004;
M99;
