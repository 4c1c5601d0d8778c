; syntax-lines-nolf: a last line without LF is read (docs/dialects/nc110.md "Reading a
; program"): the file ends with G0 X3 and no line end.
G0 X1
G0 X3