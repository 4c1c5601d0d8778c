; branches-text-padding: a quoted text of another length than the kCH reference
; is padded with blanks or cut to k characters, with a warning NC3035 (decision
; 23; codes digest §2.6). Both branches below are taken: no message.
; Expected warnings: line 7 col 17 ("OK", 2 characters, against 3: blanks added),
; line 9 col 22 ("OKAY", 4 against 2: the rest not compared).
SYVAR1.3CH="OK"
(BEQ,SYVAR1.3CH,"OK",T1)
(DIS,"PADDED NE")
"T1" (BEQ,SYVAR1.2CH,"OKAY",T2)
(DIS,"CUT NE")
"T2" (DIS,"END")
M30
