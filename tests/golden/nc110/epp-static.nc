; epp-static: static checks of (EPP,L1,L2), NC3024 (decision 22; §2.13.2.3
; L8530-8532: "an EPP that meets another EPP while it runs is not allowed"):
; an EPP inside its own range; an EPP inside another EPP's range; a range that
; ends in an RPT body (one that starts in a body: epp-cut-loop-start); a range
; whose last label comes before its first.
"A" E30=1
(EPP,A,B)
"B" E31=1
"C" E32=1
(EPP,D,E)
"D" E33=1
"E" E34=1
(EPP,C,E)
; the range F..G starts before a loop and ends in its body
"F" E1=1
(RPT,2)
"G" E2=1
(ERP)
(EPP,F,G)
; K comes before F
"K" E4=1
(EPP,K,F)
M30
