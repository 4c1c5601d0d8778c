; dis-items: (DIS,item,...) shows its items one after the other as one message
; event: a text as written; a value alone (not right after a text) as
; NAME=value; a value right after a text as the value alone; a constant as
; written; BY/IN/LI as integers, RE with 7 and LR with 10 significant digits
; (§2.13.6.1 L9582-9605: "the control shows Name = value"; §1.2.20 L615-617;
; decision 37; docs/trace.md: the text is a JSON string literal).
E1=200
E10=-1234
E20=123456789
E25=0.1
E26=1234567.8
E30=1/3
E31=123456789012
E33=-2.5
; each class alone: E1=200, E10=-1234, E20=123456789, E25=0.1 (the float
; 0.100000001 to 7 digits), E26=1234568 (the float 1234567.75 to 7 digits),
; E30=0.3333333333, E31=1.23456789e+11 (10 digits), E33=-2.5
(DIS,E1)
(DIS,E10)
(DIS,E20)
(DIS,E25)
(DIS,E26)
(DIS,E30)
(DIS,E31)
(DIS,E33)
; a value after a text: "E33=" then -2.5
(DIS,"E33=",E33)
; constants as written
(DIS,100)
(DIS,-1.50)
; a list: text, constant, text, value after the text, value after a value
(DIS,"A",1,"B",E1,E10)
; a value first, then a text: E1=200X
(DIS,E1,"X")
; system variables: UOV, TMR, RMS (100 at power-on), USB (1)
UOV=0.25
(DIS,UOV)
(DIS,TMR)
(DIS,RMS)
(DIS,USB)
; memories: SA bit 3, SK byte 7, SYVAR IN at bytes 4-5, SYVAR 3 characters
SA3=1
SK7=42
SYVAR2.IN=-7
SYVAR10.3CH="AB"
(DIS,SA3)
(DIS,SK7)
(DIS,SYVAR2.IN)
(DIS,SYVAR10.3CH)
(DIS,"T=",SYVAR10.3CH,"!")
; Cyrillic text, 13 characters (§1.2.20)
(DIS,"ИНСТРУМЕНТ=12")
; an empty text
(DIS,"")
M30
