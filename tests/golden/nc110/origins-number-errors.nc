; Origin numbers that do not exist or are out of range (NC-110 §2.13.1.1: n is 0..99 or
; an IN parameter E10-E19; §2.13.1.7: n "is tied to the records of the origins file").
; Profile frame-origins: origins 1..3; no origin 7.
; Checks (ncc check: the dry run reports each error and goes on):
; - (UAO,7), (UOT,7,X1), (RQO,7,X1): no origin 7 in the profile: NC4037 at the number 7;
; - (UAO,E10), (UOT,E10,X1) with E10 = 100 and (RQO,E10,X1) with E10 = -1: not a whole
;   number from 0 to 99: NC4057 at the operand.
(UAO,7)
(UOT,7,X1)
(RQO,7,X1)
E10=100
(UAO,E10)
(UOT,E10,X1)
E10=-1
(RQO,E10,X1)
