(an external subprogram in its own file without a header: the file name gives its number)
G01 Z#1;
M98 P2001;
M99;
