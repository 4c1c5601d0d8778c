; A field must end on the screen (78 columns): a 20-character text at column 64 would end at 83.
; The dry run of `ncc check` runs the screen statements, so it finds it (decision 61).
(SCR, ON)
(DEF, 1, 3, 64, "TWENTY CHARACTERS...")
M30
