; OUT n, value: the value must suit the field's format (a number for a numeric field).
(SCR, ON)
(DEF, 1, 3, 10, 0, 3)
(OUT, 1, "TEXT")
M30
