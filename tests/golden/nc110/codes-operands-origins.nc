; Operands of the reference-system codes UAO UOT UIO MIR URT SCF RQO (§2.13.1, seed lines 7843-8329;
; stdlib/dialects/nc110/three_letter_codes.tsv): for each code a correct block (no error), a missing
; operand (NC3016 at the closing parenthesis), an extra operand (NC3017; codes whose last operand
; repeats take at most six axes: a seventh is NC3018 at it), operands of the wrong kind (NC3018: a label
; or text where a number is needed, an expression, the letter O for 0, a number out of range, a
; non-axis), an E parameter of the wrong class (NC2016; Table 2.9, lines 7761-7827: origin numbers
; IN E10-E19, angles and factors RE E25-E29, axis values RE or LR (decision 14)), an axis twice
; (NC3019). Decisions 14 and 19. The default machine has the axes XYZABCUVW.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; UAO (§2.13.1.1): origin, then axis letters.
(UAO,1)
(UAO,E10,X,Y)
(UAO,0,X,Y,Z,A,B,C)
(UAO)
(UAO,1,X,Y,Z,A,B,C,U)
(UAO,LAB)
(UAO,O)
(UAO,E10+1)
(UAO,100)
(UAO,1.5)
(UAO,1,5)
(UAO,1,X10)
(UAO,1,Q)
(UAO,E25)
(UAO,1,X,X)
; UOT (§2.13.1.2): origin, then axes with values.
(UOT,E11,X10,YE30)
(UOT,0,X-50,Y)
(UOT)
(UOT,1)
(UOT,1,X1,Y1,Z1,A1,B1,C1,U1)
(UOT,L1,X1)
(UOT,O,X100,Y100)
(UOT,1,5)
(UOT,1,X1 X2)
(UOT,1,XE30+1)
(UOT,E25,X1)
(UOT,1,XE10)
(UOT,1,X10,X5)
; UIO (§2.13.1.3): axes with values.
(UIO,X1,YE31,Z-2.5)
(UIO)
(UIO,X1,Y1,Z1,A1,B1,C1,U1)
(UIO,XL)
(UIO,5)
(UIO,X1,YE30-1)
(UIO,XE1)
(UIO,X1,X2)
; MIR (§2.13.1.4): axis letters, none to switch mirroring off.
(MIR)
(MIR,X,Y)
(MIR,X,Y,Z,A,B,C,U)
(MIR,5)
(MIR,XE30)
(MIR,Q)
(MIR,X,X)
; URT (§2.13.1.5): one angle.
(URT,E25)
(URT,-30)
(URT,0)
(URT)
(URT,45,X)
(URT,LAB)
(URT,O)
(URT,30+15)
(URT,"45")
(URT,100000)
(URT,E30)
; SCF (§2.13.1.6): optional factor, then axis letters.
(SCF)
(SCF,3)
(SCF,E26,X)
(SCF,2,X,Y,Z,A,B,C,U)
(SCF,LAB)
(SCF,O)
(SCF,0)
(SCF,-2)
(SCF,2,5)
(SCF,E30)
(SCF,2,X,X)
; RQO (§2.13.1.7): origin, then axes with values.
(RQO,E10,YE31)
(RQO,3,X0.5)
(RQO)
(RQO,1)
(RQO,1,X1,Y1,Z1,A1,B1,C1,U1)
(RQO,O,XE35)
(RQO,1,5)
(RQO,E25,X1)
(RQO,1,XE20)
(RQO,1,X1,X2)
