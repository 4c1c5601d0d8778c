; memory-convert: a store into memory converts as a store into the E parameter of that
; class (decisions 8 and 17): BY, IN and LI round half away from zero; RE is an IEEE
; float; LR a double.
SYVAR1.BY=2.5
(DIS,SYVAR1.BY)
SYVAR1.IN=-2.5
(DIS,SYVAR1.IN)
SYVAR1.LI=0.3*10
(DIS,SYVAR1.LI)
SYVAR2.RE=0.1
E30=SYVAR2.RE
(DIS,E30)
SYVAR3.LR=0.1
E31=SYVAR3.LR
(DIS,E31)
; a value from an E parameter, and a memory copied into another (L1004 SK5=SK7)
E30=200.4
SK7=E30
SK5=SK7
(DIS,SK5)
