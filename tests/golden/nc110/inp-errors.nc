; INP's operands (§5.5): a prompt in quotes, then an E parameter or a numeric SYVAR, SA or SK. The
; user screen's forms (a field number as the prompt, a field for the answer) are not supported yet.
(INP, "X")
(INP, X, E40)
(INP, "X", E5.5)
(INP, "X", SYVAR.10CH)
(INP, "X", SYVAR2.BY, 300)
(INP, 1, E40, 2)
(INP, "X", E40, 2)
M30
