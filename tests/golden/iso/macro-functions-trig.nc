(trigonometric functions in degrees: SIN COS TAN ASIN ACOS ATAN, and the two-argument ATAN[a]/[b])
G01 X[SIN[30]] Y[COS[60]] Z[TAN[45]] F100;
G01 X[SIN[-90]] Y[COS[180]] Z[TAN[-45]];
G01 X[SIN[390]] Y[COS[0]] Z[TAN[0]];
(the inverse functions give degrees)
G01 X[ASIN[0.5]] Y[ACOS[0.5]] Z[ATAN[1]];
G01 X[ASIN[-1]] Y[ACOS[-1]] Z[ATAN[-1]];
(ATAN[a]/[b] is the angle of the point [b, a]: all four quadrants)
G01 X[ATAN[1]/[1]] Y[ATAN[1]/[-1]] Z[ATAN[-1]/[-1]];
G01 X[ATAN[-1]/[1]] Y[ATAN[0]/[-1]] Z[ATAN[1]/[0]];
(another function followed by /[b] is a division: SIN[30]/[2] = 0.25)
#1=SIN[30]/[2];
(functions nest and take expressions)
#2=SIN[ASIN[0.25]*2+[10-10]];
#3=ATAN[SQRT[3]];
G01 X#1 Y#2 Z#3;
(the seed's example Y[#2+SIN[#3]*#4])
#2=1;
#3=30;
#4=4;
G01 X0 Y[#2+SIN[#3]*#4] Z0;
M30;
