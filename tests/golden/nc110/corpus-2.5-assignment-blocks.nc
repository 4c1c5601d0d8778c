; corpus-2.5-assignment-blocks: copy of corpus/nc110/part1/2.5-assignment-blocks.nc (§2.5
; seed L1534-1536). Expect: E30 = 28.5 (a calculation variable, class LR); UOV = 1.5 (a
; global system variable). Changed: the corpus had already replaced the manual's Cyrillic
; Е30 and р2 by Latin letters (the as-printed homoglyphs: syntax-homoglyphs.nc); the GTL
; point p2 = X10 Y25 is left out (GTL is not supported yet: corpus-2.5-assignment-
; blocks-gtl.nc); DIS blocks added.
E30 = 28.5
UOV=1.5
(DIS,E30)
(DIS,UOV)
