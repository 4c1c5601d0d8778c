modal-feed-mode-clears-f: changing the feed mode clears F, which means something else in the new mode (decision 23)
%
N1 G90 G94 G01 X1. F100. S100 M03
N2 G95 X2. (NC4001, F was per minute)
N3 X3. F0.1
N4 G94 X4. (NC4001 again)
N5 M02
