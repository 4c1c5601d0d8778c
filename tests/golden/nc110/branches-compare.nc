; branches-compare: (Bcc,VAR1,VAR2,LABEL) jumps when VAR1 cc VAR2 holds, else
; goes on; (BNC,LABEL) always jumps (§2.13.2.4 Table 2.10, seed L8552-8562).
; Values compare exactly, as doubles (decision 23; §2.13.2.4 L8599-8603: reals
; are compared against a threshold by the programmer). Each test is followed by
; a message that shows only when the branch is NOT taken.
(BGT,2,1,G1)
(DIS,"BGT 2 1 NOT TAKEN")
"G1" (BGT,1,2,G2)
(DIS,"BGT 1 2 NOT TAKEN")
"G2" (BGT,1,1,G3)
(DIS,"BGT 1 1 NOT TAKEN")
"G3" (BLT,1,2,L1)
(DIS,"BLT 1 2 NOT TAKEN")
"L1" (BLT,2,1,L2)
(DIS,"BLT 2 1 NOT TAKEN")
"L2" (BLT,1,1,L3)
(DIS,"BLT 1 1 NOT TAKEN")
"L3" (BEQ,1,1.0,Q1)
(DIS,"BEQ 1 1.0 NOT TAKEN")
"Q1" (BEQ,1,2,Q2)
(DIS,"BEQ 1 2 NOT TAKEN")
"Q2" (BNE,1,2,N1)
(DIS,"BNE 1 2 NOT TAKEN")
"N1" (BNE,1,1,N2)
(DIS,"BNE 1 1 NOT TAKEN")
"N2" (BGE,1,1,GE1)
(DIS,"BGE 1 1 NOT TAKEN")
"GE1" (BGE,2,1,GE2)
(DIS,"BGE 2 1 NOT TAKEN")
"GE2" (BGE,1,2,GE3)
(DIS,"BGE 1 2 NOT TAKEN")
"GE3" (BLE,1,1,LE1)
(DIS,"BLE 1 1 NOT TAKEN")
"LE1" (BLE,1,2,LE2)
(DIS,"BLE 1 2 NOT TAKEN")
"LE2" (BLE,2,1,LE3)
(DIS,"BLE 2 1 NOT TAKEN")
"LE3" (BNC,U1)
(DIS,"BNC NOT TAKEN")
; exact: 0.1+0.2 is 0.30000000000000004 as a double
"U1" E30=0.1+0.2
(BEQ,E30,0.3,X1)
(DIS,"BEQ 0.1+0.2 0.3 NOT TAKEN")
"X1" (BGT,E30,0.3,X2)
(DIS,"BGT 0.1+0.2 0.3 NOT TAKEN")
; an RE parameter holds 0.1 as a float, 0.100000001490116...: not 0.1
"X2" E25=0.1
(BEQ,E25,0.1,X3)
(DIS,"BEQ E25 0.1 NOT TAKEN")
"X3" (BEQ,E25,E25,X4)
(DIS,"BEQ E25 E25 NOT TAKEN")
; 0.5 is exact in a float
"X4" E26=0.5
(BEQ,E26,0.5,X5)
(DIS,"BEQ E26 0.5 NOT TAKEN")
; parameters of different classes: BY 200 = IN 200 = LI 200 = LR 200
"X5" E1=200
E10=200
E20=200
E31=200
(BEQ,E1,E10,X6)
(DIS,"BEQ E1 E10 NOT TAKEN")
"X6" (BEQ,E20,E31,X7)
(DIS,"BEQ E20 E31 NOT TAKEN")
; negative values
"X7" E11=-5
(BLT,E11,-4.5,X8)
(DIS,"BLT E11 -4.5 NOT TAKEN")
"X8" (BGE,-4.5,E11,X9)
(DIS,"BGE -4.5 E11 NOT TAKEN")
; a backward branch: a loop that runs while E2 < 3
"X9" E2=E2+1
(BLT,E2,3,X9)
(DIS,E2)
M30
