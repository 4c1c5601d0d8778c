(codes outside the list, spec 4 and A-06: an unknown G or M code is NC3003 or NC3004 when written, NC4049 at run time when it comes from a variable; a code number must be whole, NC3030; a vacant variable gives no code, decision 3; the dry run of check ends at the first NC4049, as at a division by zero, so G10 from #3 at line 13 is not reported)
G90 G00 X0 Y0 Z0;
G10 X1;
G61;
G1.5 X1;
M19;
M50;
M3.1;
G#1 X1;
#2=50;
M#2;
#3=10;
G#3 X1;
M30;
