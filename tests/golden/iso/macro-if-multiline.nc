(multi-line IF / ELIF / ELSE: braces on their own lines and on the same line, several ELIFs)
G01 X0 Y0 Z0 F100;
#1=2;
(braces on their own lines)
IF [#1 GT 1]
{
G01 X1;
G01 Y1;
}
ELIF [#1 GT 0]
{
G01 X99;
}
ELSE
{
G01 X98;
}
(all on one line; the first branch is false, ELIF is true)
IF [#1 GT 2] {G01 X97;} ELIF [#1 EQ 2] {G01 X2; G01 Y2;} ELSE {G01 X96;}
(ELSE is taken)
IF [#1 GT 2] {G01 X95;} ELIF [#1 LT 0] {G01 X94;} ELSE {G01 X3;}
(braces at the end of the head line and the body on its own lines)
IF [#1 EQ 0] {
G01 X93;
} ELIF [#1 EQ 1] {
G01 X92;
} ELIF [#1 EQ 2] {
G01 X4;
#2=5;
} ELIF [#1 EQ 2] {
G01 X91;
} ELSE {
G01 X90;
}
G01 X#2;
(several ELIFs chosen by a counter in a loop: 1 2 3 and then ELSE)
#3=1;
WHILE [#3 LE 4] DO1;
IF [#3 EQ 1] {G01 Z1;}
ELIF [#3 EQ 2] {G01 Z2;}
ELIF [#3 EQ 3] {G01 Z3;}
ELSE {G01 Z4;}
#3=#3+1;
END1;
(IF without ELSE, false: nothing runs; true: its body runs)
IF [#1 EQ 3] {G01 X89;}
IF [#1 EQ 2] {G01 X6;}
(an empty body)
IF [#1 EQ 2] {} ELSE {G01 X88;}
G01 X7;
M30;
