(M97 errors: E-29 a target block before M30, a block no block carries, no P, P not a whole number)
N10 G01 X1 F100;
M97 P10;
M97 P300;
M97;
M97 P10.5;
M97 P#1;
M30;
N100 G01 X2;
M99;
