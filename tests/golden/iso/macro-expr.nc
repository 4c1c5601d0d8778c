(expressions: precedence of * / over + -, unary minus, nested brackets, MOD)
#1=2+3*4;
#2=[2+3]*4;
#3=10-4-3;
#4=24/4/2;
G01 X#1 Y#2 Z#3 F100;
G01 X#4 Y[2*-3] Z[-2*3+1];
(unary minus before a bracket and a variable; double sign)
#5=-[#1-20];
#6=--#5;
#7=-#5*-2;
G01 X#5 Y#6 Z#7;
(nested brackets)
#8=[[[1+2]*[3+4]]-[10/[4+1]]]*2;
G01 X#8 Y[[#1+#2]/[#3+#4]] Z[1-[2-[3-[4-5]]]];
(MOD binds like * and /)
#9=17 MOD 5;
#10=2+17 MOD 5*3;
#11=-7 MOD 3;
#12=7.5 MOD 2;
G01 X#9 Y#10 Z#11;
G01 X#12 Y0 Z0;
(decimals: 1/3 shows four decimals in the trace)
G01 X[1/3] Y[2/3] Z[-1/3];
M30;
