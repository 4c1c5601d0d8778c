; EXE, REL, WAI and SND: the operands ncc refuses (NC-110 §4.1, decision 63; process-operands: the
; forms it takes): no operand, a process 0 or 6, an E parameter not of class BY, a device beyond MP3,
; a program name in lower case (the manual's "Progl"), a wait for a real, a text or a bit with '<' or
; '>', no value, no memory, a second operand, REL with one, a program that is not in the library.
M30
(EXE)
(WAI)
(SND)
(EXE,6,PROG1)
(SND,0)
(WAI,E25)
(EXE,2,PROG1/MP5)
(EXE,2,Progl)
(WAI,SA10.LR=1)
(WAI,SYVAR1.4CH=1)
(WAI,SA10>1)
(WAI,SA10=)
(WAI,E1=1)
(WAI,1,2)
(REL,1)
(EXE,3,NOPROG)
