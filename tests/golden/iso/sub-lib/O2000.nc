(an external subprogram in its own file: the library's O2000)
O2000;
G01 X#1;
#1=#1+1;
M99;
