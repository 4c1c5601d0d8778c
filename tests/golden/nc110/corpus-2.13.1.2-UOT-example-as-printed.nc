; Copy of corpus part4/2.13.1.2-UOT-example.nc (NC-110 §2.13.1.2, seed lines 15551-15556)
; with the code as printed: the Latin letter O for the origin number 0 in (UAO,O) and
; (UOT,O,...) (both renderings; also (UAO,O) of §2.13.1.1). Only the annotations after
; " - ", the list numbers and the elision lines are dropped.
; Checks (decision 19): each O is an error with a hint, at its operand (NC3018):
; lines 7, 8 and 10, column 6; (UOT,1,...) on line 9 is correct.
(UAO,O)
(UOT,O,X100,Y100)
(UOT,1,X-250,Y-50)
(UAO,O)
