; cls-modal: a called program shares the caller's E parameters and modal state:
; nothing is saved or restored (§2.13.2.2 "parametric" L8456-8458; decision 21;
; the manual's SUB800 ends with (UAO,0) (URT,0), SUB700 with G80 G90).
; E30 is the parameter; FLOWM sets E31 = 2*E30 = 14, moves G1 G91 X5 F200 and
; moves the origin to X100: the tool at machine X5 is at X-95 from it.
N1 E30=7
N2 (CLS,FLOWM)
; still G01 G91 F200: X5 more -> X-90 (machine X10), no new feed_rate event
N3 X5
N4 (DIS,E31)
; G90 G00 X0 -> machine X100 = X0 of the temporary origin; then origin 0 again
N5 G90 G X0
N6 (UAO,0)
N7 M30
