O2001 (an external subprogram in its own file, the library's O2001: the header comes first)
G01 X#1;
#1=#1+1;
M99;
