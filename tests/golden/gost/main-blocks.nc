main-blocks: a colon block is a main block that should hold everything needed to resume; a run may start there (GOST 20999 §2.6, decision 9, NC3008)
%1
N1 G90 G17 G00 X1. Y1. S500 M03 T1
:10 G90 G17 G01 X10. Y0 F100 S600 M03 T2 (complete - no warning)
N11 X20.
:20 G91 G00 X5. (incomplete - NC3008 names the plane, F, S with a spindle function, T)
N21 X5.
N22 M30
