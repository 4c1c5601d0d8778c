(vacant variables: a never-set variable leaves its word out, copies as vacant, reads 0 in arithmetic)
G01 X1 Y2 Z3 F100;
(X#5: #5 was never set, the X word is left out: X stays 1)
G01 X#5 Y5;
(a copy stays vacant)
#2=#5;
G01 X#2 Y6;
(arithmetic reads it as 0)
#3=#5+0;
G01 X#3 Y7;
G01 X4;
(X-#5 and X[#5] leave X out too)
G01 X-#5 Y8;
G01 X[#5] Y9;
(-#5 in an expression is arithmetic: 0)
#4=-#5;
G01 X#4 Y10;
(EQ and NE tell vacant from 0; the order comparisons read it as 0)
IF [#5 EQ #0] THEN G01 Y11;
IF [#5 EQ 0] THEN G01 Y12;
IF [#5 NE 0] THEN G01 Y13;
IF [#5 LT 1] THEN G01 Y14;
IF [#5 GE 0] THEN G01 Y15;
IF [#5 GT -1] THEN G01 Y16;
IF [#2 EQ #0] THEN G01 Y17;
IF [#3 EQ #0] THEN G01 Y18;
IF [#3 EQ 0] THEN G01 Y19;
(an assignment of #0 makes a variable vacant again)
#3=#0;
IF [#3 EQ #0] THEN G01 Y20;
G01 X5 Z#3;
M30;
