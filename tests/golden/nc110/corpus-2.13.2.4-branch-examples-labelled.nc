; corpus-2.13.2.4-branch-examples-labelled: the four blocks of corpus
; part4/2.13.2.4-branch-examples.nc (§2.13.2.4, seed L8577-8585) with their
; labels defined, each run once not taken and once taken:
;   N10 to END if E1 > 123; N20 to LAB1 if the boolean SA3 is on (= 1);
;   N30 to START if E1 <> E5; N40 to LAB1 if SYVAR bytes 1-2 are "OK".
; Added: the values, the labels, messages (where a branch is NOT taken, and
; where one lands), repeated N numbers (decision 7), the counter E30 and M30.
N1 E1=123
N2 E5=123
; not taken: 123 is not > 123; SA3 is 0; E1 = E5; SYVAR bytes 1-2 are zero
N10 (BGT,E1,123,END)
N11 (DIS,"N10 NOT TAKEN")
N20 (BEQ,SA3,1,LAB1)
N21 (DIS,"N20 NOT TAKEN")
N30 (BNE,E1,E5,START)
N31 (DIS,"N30 NOT TAKEN")
N40 (BEQ,SYVAR1.2CH,"OK",LAB1)
N41 (DIS,"N40 NOT TAKEN")
; taken: N20 (forwards) and N40 (backwards) land on LAB1, then N30, then N10
N50 SA3=1
N20 (BEQ,SA3,1,LAB1)
N51 (DIS,"NOT REACHED")
"LAB1" N52 E30=E30+1
N53 (DIS,"AT LAB1 ",E30)
N54 (BGE,E30,2,NEXT)
N55 SYVAR1.2CH="OK"
N40 (BEQ,SYVAR1.2CH,"OK",LAB1)
N56 (DIS,"NOT REACHED")
"NEXT" N57 E5=5
N30 (BNE,E1,E5,START)
N58 (DIS,"NOT REACHED")
"START" N59 E1=124
N10 (BGT,E1,123,END)
N60 (DIS,"NOT REACHED")
"END" N61 (DIS,"AT END")
N62 M30
