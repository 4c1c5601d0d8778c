; OUT needs the screen on; after (SCR,OFF) a field shown before cannot be shown again.
(SCR, ON)
(DEF, 1, 3, 10, "X")
(OUT, 1)
(SCR, OFF)
(OUT, 1)
M30
