; dly-errors: the time of (DLY,t) is a constant from 0 to 32 seconds or one LR
; parameter (E30 on) (§2.13.6.2 L9625-9629: "max. 32 seconds ... a real of
; double precision (E30...)"; decision 14). One error per line.
(DLY,33)
(DLY,32.001)
(DLY,-1)
(DLY,E25)
(DLY,E1)
(DLY)
(DLY,1,2)
(DLY,E30+2)
M30
