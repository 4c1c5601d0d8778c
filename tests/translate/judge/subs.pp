Subprograms, R parameters and G73 counted jumps, as a structured translation keeps
them (judge_linuxcnc.py).
%7
N10 R1 5 R2 2.5 G0 X0 Y0 Z10
N20 G1 F200 G71 L100 Q3
N30 G26 R1 R2
N40 X R1 Y-R2
N50 G91 X5
N60 Y2 G73 L50 Q2
N70 G90 G0 Z20 M30
N100 G79 L100
N110 G91 G1 X R2 Y1
N120 G90 G70
*
