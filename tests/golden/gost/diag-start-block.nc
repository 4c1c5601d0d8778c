diag-start-block: a program with the main block 20 only (NC4022 for --start-block 5)
%
N10 G00 X50 Y50
:20 G01 G90 G17 X10 Y0 F100 S500 M03 T1
N30 X20
N40 M30
