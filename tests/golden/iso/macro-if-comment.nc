(a comment line or an empty line between a body's '}' and its ELIF or ELSE)
#1=2;
IF [#1 EQ 1] {
G01 Y1 F100;
}

ELIF [#1 EQ 2] {
G01 Y2 F100;
}
IF [#1 EQ 1] {
G01 X1 F100;
}
(the ELSE branch follows)
ELSE {
G01 X2 F100;
}
M30;
