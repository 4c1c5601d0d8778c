(SQRT ABS EXP LN FIX FUP, and ROUND: whole in an assignment, 3 decimals after an address in G21, 4 in G20)
G21;
G01 X[SQRT[16]] Y[SQRT[2]] Z[SQRT[0]] F100;
G01 X[ABS[-2.5]] Y[ABS[3]] Z[ABS[-0]];
G01 X[EXP[0]] Y[EXP[1]] Z[EXP[-1]];
G01 X[LN[1]] Y[LN[EXP[2]]] Z[LN[0.5]];
(FIX towards zero, FUP away from zero)
G01 X[FIX[1.7]] Y[FIX[-1.7]] Z[FIX[2]];
G01 X[FUP[1.2]] Y[FUP[-1.2]] Z[FUP[2]];
(ROUND in an assignment gives a whole number; half-way goes away from zero)
#1=ROUND[1.23456];
#2=ROUND[2.5];
#3=ROUND[-2.5];
G01 X#1 Y#2 Z#3;
(ROUND after an address keeps 3 decimals in G21: 1.2346 would show otherwise)
G01 X[ROUND[1.23456]] Y[ROUND[-0.0005]] Z[ROUND[1.0004]];
(the rounded value stored in a variable first is whole)
#4=ROUND[1.23456]+0.5;
G01 X#4 Y0 Z0;
(G20: 4 decimals after an address)
G20;
G01 X[ROUND[1.23456]] Y[ROUND[1.00004]] Z[ROUND[1.00005]];
#5=ROUND[1.23456];
G01 X#5;
M30;
