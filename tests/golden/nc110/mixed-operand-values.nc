; Operand values from E parameters out of range at run time (NC-110 §2.13.1.6 SCF factor,
; §2.13.5.5 zone 1..3); decisions 19 and 28: NC4057 at the operand.
; Checks (ncc check's dry run reports each): (ASC,E1) with E1 = 4, (DSA,E1,...) with
; E1 = 0: the zone must be a whole number from 1 to 3; (SCF,E25) with E25 = -1: the
; factor must be greater than 0. Each message, at the parameter, names the operand (the
; zone, the scale factor) and its value and says what it must be.
E1=4
(ASC,E1)
E1=0
(DSA,E1,X0 X1,Y0 Y1)
E25=-1
(SCF,E25)
