; FLOWB (cls-depth): called from the main program (level 1), calls FLOWC (level 2).
E30=E30+1
(CLS,FLOWC)
