; branches-text: SYVARi.kCH names the k bytes from byte i (k = 1 when omitted);
; BEQ and BNE compare them with a quoted text of the same length, or with
; another kCH reference (§2.13.2.4 L8585-8597; decision 17: a shorter text
; stored is padded with blanks; decision 23). A message shows only when a
; branch is NOT taken.
; bytes 1..3 = "O" "K" " " (the store pads "OK" to 3 characters)
SYVAR1.3CH="OK"
(BEQ,SYVAR1.3CH,"OK ",T1)
(DIS,"SYVAR1.3CH NE OK_")
"T1" (BEQ,SYVAR1.2CH,"OK",T2)
(DIS,"SYVAR1.2CH NE OK")
; the text may come first
"T2" (BEQ,"OK",SYVAR1.2CH,T3)
(DIS,"OK NE SYVAR1.2CH")
; .CH is one character: byte 1 = "O"
"T3" (BEQ,SYVAR1.CH,"O",T4)
(DIS,"SYVAR1.CH NE O")
; the index counts bytes: SYVAR2.2CH is bytes 2..3 = "K "
"T4" (BNE,SYVAR2.2CH,"K ",T5)
(DIS,"SYVAR2.2CH IS K_")
; not equal: BNE taken, BEQ not
"T5" (BNE,SYVAR1.2CH,"OX",T6)
(DIS,"SYVAR1.2CH IS OX")
"T6" (BEQ,SYVAR1.2CH,"OX",T7)
(DIS,"SYVAR1.2CH NOT OX")
; two references of the same length: bytes 1..2 against bytes 11..12, zero
"T7" (BEQ,SYVAR1.2CH,SYVAR11.2CH,T8)
(DIS,"SYVAR1.2CH NE SYVAR11.2CH")
"T8" SYVAR11.2CH="OK"
(BEQ,SYVAR1.2CH,SYVAR11.2CH,T9)
(DIS,"SYVAR1.2CH NE SYVAR11.2CH AGAIN")
; SK memory holds texts too
"T9" SK7.3CH="RIF"
(BEQ,SK7.3CH,"RIF",T10)
(DIS,"SK7.3CH NE RIF")
"T10" (DIS,"END")
M30
