; corpus-1.2.32-branch-examples-fixed: the four branches of corpus
; part1/1.2.32-branch-examples.nc (§1.2.32, seed L855-869) with their labels
; defined, each run once not taken and once taken:
;   N10 jumps to END if E1 > 123; N20 to LAB if the PLC bit SA3 is 1;
;   N30 to START if E1 <> E5; N40 to END if SYVAR bytes 1-2 are "OK".
; Corrected: N40 (BEQ,SYVAR1.CH,OK,END) reads (BEQ,SYVAR1.2CH,"OK",END), as
; §2.13.2.4 L8585 prints it (".CH" is one character; texts are quoted).
; Added: the values, the labels, the messages (shown when a branch is NOT
; taken or where it lands), the repeated N numbers (decision 7) and M30.
N1 E1=123
N2 E5=123
; not taken: 123 is not > 123; SA3 is 0; E1 = E5; SYVAR bytes 1-2 are zero
N10 (BGT,E1,123,END)
N11 (DIS,"N10 NOT TAKEN")
N20 (BEQ,SA3,1,LAB)
N21 (DIS,"N20 NOT TAKEN")
N30 (BNE,E1,E5,START)
N31 (DIS,"N30 NOT TAKEN")
N40 (BEQ,SYVAR1.2CH,"OK",END)
N41 (DIS,"N40 NOT TAKEN")
; taken: SA3 = 1 -> LAB; E5 = 5 -> START; "OK" -> END
N50 SA3=1
N20 (BEQ,SA3,1,LAB)
N51 (DIS,"NOT REACHED")
"LAB" N52 E5=5
N30 (BNE,E1,E5,START)
N53 (DIS,"NOT REACHED")
"START" N54 SYVAR1.2CH="OK"
N40 (BEQ,SYVAR1.2CH,"OK",END)
N55 (DIS,"NOT REACHED")
; at END the first time (E30=1) E1 becomes 124 and N10 jumps back to END;
; the second time (E30=2) the program ends
"END" N70 E30=E30+1
N71 (DIS,"AT END ",E30)
N72 (BGE,E30,2,FIN)
N73 E1=124
N10 (BGT,E1,123,END)
N74 (DIS,"NOT REACHED")
"FIN" N75 M30
