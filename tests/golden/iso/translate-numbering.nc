(translate-numbering: what a translation back gives again, docs/translate.md "Round trips": ISO's #500+n is NC-110's E n and pp's R n, its N9001 up NC-110's K1 up; #1 is set before anything reads it, so it gets no 0 at the start)
#1=#530+1
#530=2
IF [#1 GT 1] GOTO 9002
G01 X#530 F100
N9002 G00 X#1
(a comment alone)
M98 P100
M30
O100
G91 G01 Y1 F100
G90
M99
