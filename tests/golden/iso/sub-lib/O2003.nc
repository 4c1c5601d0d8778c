O2003 (a library macro dividing by its argument A)
#2=10/#1;
G01 X#2;
M99;
