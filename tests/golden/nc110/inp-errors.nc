; INP's operands (§5.5): a prompt in quotes or a screen field's number, then an E parameter or a
; SYVAR, SA or SK (a number or a text: screen-text), then the field that shows the answer. The last two are right in form:
; the dry run finds no field 1 holding a prompt (the program defines none) and stops there.
(INP, "X")
(INP, X, E40)
(INP, "X", E5.5)
(INP, "X", SYVAR2.BY, 300)
(INP, 1, E40, 2)
(INP, "X", E40, 2)
M30
