(E-32: the numbers of '[' and ']' in a block differ; each block is reported once, the others still read)
#1=[2+3;
#2=2+3];
G01 X[[#1+1] F100;
IF [#1 GT [2] GOTO 10;
#3=SIN[30]];
(a bracket in a comment does not count)
#4=[1+2] (see [A-40);
G01 X1 F100;
N10 M30;
