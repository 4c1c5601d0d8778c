; docs/dialects/nc110.md decision 19 (§2.13, Table 2.9 seed lines 7761-7827): an operand of a
; three-letter code is a constant or ONE E parameter, never an expression (NC3018, naming what is
; left over); a code takes at most six axis operands (a seventh is NC3018) and each axis once
; (NC3019, at the second); the letter O where the digit 0 is meant is NC3018 with that hint (the
; manual prints (UAO,O) line 7888, (UOT,O,X100,Y100) line 7924, (URT,O) line 8317, (RQO,O,XE35)
; line 943, (RQO,O,YE32) line 10314). Blanks may stand around operands and commas (lines 8618,
; 8985, 9547 as printed, LAB read as L1).
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
"L1" M30
; Blanks around operands and commas: no error.
(BLT, E44, E43, L1)
N57 (UOT,0,X-50,Y)
N1  (DSA, 1,X-300 X-100, Y-100Y100)
( URT , 45 )
; Expressions: + - / after a constant or an E parameter, in each numeric operand (RPT: NC3021 too).
(UAO,1+1)
(RPT,E1-1)
(URT,E25/2)
(SCF,E26+E27)
(DLY,E30+E31)
(ASC,E1+1)
(UIO,X10+5)
(DLO,X-10 X10/2)
(DIS,"X=",E30/2)
(BGT,E1,E2+1,L1)
; Six axis operands are allowed, a seventh is NC3018 (at the seventh).
(MIR,X,Y,Z,A,B,C)
(UIO,X1,Y1,Z1,A1,B1,C1)
(DLO,X-1 X1,Y-1 Y1,Z-1 Z1,A-1 A1,B-1 B1,C-1 C1)
(MIR,X,Y,Z,A,B,C,U)
(UIO,X1,Y1,Z1,A1,B1,C1,U1)
; Each axis once: NC3019 at the second operand of that axis.
(UAO,1,Y,X,Y)
(UOT,1,Y1,X1,YE30)
(DLO,X1 X2,Y1 Y2,X3 X4)
(DPI,Y,Y)
; The letter O for the digit 0, as the manual prints it.
(UAO,O)
(UOT,O,X100,Y100)
N104 (URT,O)
(RQO,O,XE35)
N503 (RQO,O,YE32)
