; Texts in memory on the user screen and from the keyboard (decisions 60, 61): DEF takes a text
; variable as its initial value (its width the variable's), OUT shows a field with one, INP enters
; one ("text" answers in the input script; shorter ones are filled with blanks). A left-out column
; is 1, a left-out prompt none. screen-text.input answers "BOLT" and 7.5.
SYVAR10.6CH="PART A"
(SCR,ON)
(DEF,1,2,,SYVAR10.6CH)
(DEF,2,3,,"NAME? ")
(DEF,3,3,7,"      ")
(OUT)
(INP,2,SYVAR20.6CH,3)
(OUT,1,SYVAR20.6CH)
(INP,,E40)
(DIS,SYVAR20.6CH,"/",E40)
M30
