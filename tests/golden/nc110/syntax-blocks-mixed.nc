; syntax-blocks-mixed: a block holds one instruction (§2.5; decision 6: a second '=' is
; NC1028). Expect NC1028 for each line: two assignments (line 5, at the second
; assignment), a code followed by an assignment (line 6), an ISO block followed by a code
; (line 7), an ISO block followed by an assignment (line 8).
E1=2 E2=3
(DIS,"A") E1=1
G0 X1 (DIS,"A")
G0 X1 E1=2
