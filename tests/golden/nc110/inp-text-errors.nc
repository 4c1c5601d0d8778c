; Answers that do not fit the variable (decision 60), NC4091 at the INP: a number for a text
; (inp-text-errors: 12), a text longer than the variable (.long: "TOOLONG" for 4 bytes), a text
; for a number (.text: "AB" fits the first, "X" is given to E40).
(INP,"NAME ",SYVAR20.4CH)
(INP,"FEED ",E40)
M30
