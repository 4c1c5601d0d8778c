(a multi-line IF as the last statement of another IF body: its '}' is followed by the outer '}')
#1=1;
IF [#1 EQ 1] {
IF [#1 EQ 1] {
G01 X1 F100;
}
}
G01 X2;
M30;
