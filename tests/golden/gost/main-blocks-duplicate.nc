main-blocks-duplicate: --start-block starts at the first main block of that number on the medium (decision 11)
%1
N1 G00 X1.
:5 G90 G17 G00 X5. (the first main block 5)
N2 M02
%2
:5 G90 G17 G00 Y5. (the second)
N3 M30
