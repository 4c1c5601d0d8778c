%
O3001(STEP);
(a macro of a shop's library: its file is named by the number alone);
#3=#1/#2;
G91G1X#3F100;
G90;
M99;
%
