; FLOWL (cls-labels): jumps to "MAIN", a label of the calling program only.
"L" E30=1
(BNC,MAIN)
