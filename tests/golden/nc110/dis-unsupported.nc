; dis-unsupported: the manual's (DIS,"c1=",c1) and (DIS,"l2=",l2) show GTL
; elements (§2.13.6.1 L9604-9615). GTL is not supported yet: the dialect reports
; GTL as NC3034 (docs/dialects/nc110.md: "Those parse and are reported as not
; supported yet"); expected NC3034 at c1 (line 7) and l2 (line 8), not NC3028.
; The manual's copy writes a Cyrillic с (line 9): NC1027 naming the Latin letter c
; (decision 2), not NC3028. Text not closed (line 10): NC1025; empty item (line 11): NC3016.
(DIS,"c1=",c1)
(DIS,"l2=",l2)
(DIS,"с1=",с1)
(DIS,"OPEN)
(DIS,E1,)
M30
