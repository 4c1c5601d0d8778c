; translate-numbering: what a translation back gives again (docs/translate.md, "Round trips"):
; NC-110's E n is ISO's #500+n, its labels K1 up ISO's N9001 up and a label N7 the block N7;
; E31 is set before anything reads it, so it gets no 0 at the start; E30 is read first.
E31=E30+1
E30=2
(BGT,E31,1,K2)
G01 XE30 F100
"K2" G00 XE31
(BNC,N7)
G00 X5
"N7" G00 X6
M30
