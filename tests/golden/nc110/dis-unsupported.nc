; dis-unsupported: the manual's (DIS,"c1=",c1) and (DIS,"l2=",l2) show GTL
; elements (§2.13.6.1 L9604-9615). DIS shows values and texts; a GTL element is
; neither: NC3018 at c1 (line 7) and l2 (line 8) says that FEP, FEL and FEC read its
; numbers (decision 80).
; The manual's copy writes a Cyrillic с (line 9): NC1027 naming the Latin letter c
; (decision 2), not NC3028. Text not closed (line 10): NC1025; empty item (line 11): NC3016.
(DIS,"c1=",c1)
(DIS,"l2=",l2)
(DIS,"с1=",с1)
(DIS,"OPEN)
(DIS,E1,)
M30
