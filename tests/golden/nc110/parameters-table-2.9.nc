; parameters-table-2.9: the programming examples of Table 2.9 (seed L7761-7827; corpus/
; nc110/part3/2.12-table-2.9-examples.nc), one E parameter of the class the place takes
; (decision 14): BY in G, M, RPT; IN in the UAO/UOT origin number, T, S; RE in F, URT,
; SCF, UGF; LR in the axes, R, TMR, UOV. Corrected: the Cyrillic МЕ3 and ТЕ14.Е15 made
; Latin; the elided UOT axes "X..,Y.." given as XE36,YE37. Left out: PE29 (an indexing
; axis, not on this machine), KE34 (a helix pitch) and vE35 (cutter radius compensation,
; not supported yet). Values supplied first. Expect from the run: M08 coolant flood; T1.1
; selected; S1200; origin 0 and no transform; the rapid and the linear move twice (RPT
; with E9 = 2); the arc R5 (RE33) from X10 to X20, cw, centre X15. ncc check: no error.
E1=1
E2=0
E3=8
E9=2
E10=0
E11=0
E14=1
E15=1
E16=1200
E25=0
E26=1
E27=250
E28=30
E32=10
E33=5
E36=0
E37=0
E38=1.5
E40=0.5
ME3
TE14.E15
SE16
(UAO,E10)
(UOT,E11,XE36,YE37)
(URT,E25)
(SCF,E26)
UGF=E28
TMR=E38
UOV=E40
(RPT,E9)
GE2 XE33
GE1 XE32 FE27
(ERP)
G2 X20 Y0 RE33
(DIS,UGF)
(DIS,TMR)
(DIS,UOV)
