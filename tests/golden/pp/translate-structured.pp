translate-structured: what a structured translation keeps (docs/translate.md): R
parameters as #500 on, G26-G29 formulas as assignments rounded to R's 0.001, G71
calls of a subprogram written once, the G73 counted jump as a loop.
%7
N10 R1 5 R2 2.5 G0 X0 Y0 Z10
N20 G1 F200 G71 L100 Q3
N30 G26 R1 R2
N40 G29 R1 3             "R1 = 2.5"
N50 X R1 Y-R2
N60 G91 X5
N70 Y2 G73 L60 Q2
N80 G90 G0 Z20 M30
N100 G79 L100
N110 G91 G1 X R2 Y1
N120 G90 G70
*
