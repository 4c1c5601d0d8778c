; syntax-comments-errors: ';' starts a comment only as the first character of a block
; (§2.5 L1509-1519, §2.4.4 L1450-1452: the leading fields belong to the other blocks;
; decision 5). Each line below is NC1026 at the ';'.
N10 G1 X10 F100 ;comment
N5 ;x
/;x
"L1";x
E1=2 ;x
(DIS,"A");x
