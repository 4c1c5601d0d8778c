; Operands of the reference-system and mixed codes (NC-110 §2.13.1, §2.13.5, Table 2.9);
; decision 19: an operand is a constant or one E parameter of the class the manual
; names, never an expression; at most six axis operands, each axis once; the letter O
; for the digit 0 is an error with a hint. All found by ncc check, one per block.
; Checks, in order:
; - an axis twice (NC3019, at the second): UAO, UOT, UIO, MIR, SCF, RQO, DPI, DTL, DLO,
;   DSA;
; - a wrong operand (NC3018, at it): the letter O in (URT,O); 1.5 and 100 as origins;
;   an expression E25+1; a scale factor 0; zone 4; (CTL,X);
; - a parameter of another class (NC2016): an LR parameter as the origin (IN E10-E19)
;   and as the angle (RE E25-E29);
; - seven axes in (SCF) (NC3018 at the seventh);
; - a missing operand (NC3016): (UOT,0), (URT), a DSA with one pair.
(UAO,1,X,X)
(UOT,0,X1,X2)
(UIO,Y1,Y2)
(MIR,Z,Z)
(SCF,2,X,X)
(RQO,1,X1,X1)
(DPI,Z,Z)
(DTL,X0.1,X0.2)
(DLO,X-1 X1,X-2 X2)
(DSA,1,X0 X1,X2 X3)
(URT,O)
(UAO,1.5)
(UAO,100)
(URT,E25+1)
(SCF,0)
(DSA,4,X0 X1,Y0 Y1)
(CTL,X)
(UAO,E30)
(URT,E30)
(SCF,2,X,Y,Z,A,B,C,U)
(UOT,0)
(URT)
(DSA,1,X0 X1)
