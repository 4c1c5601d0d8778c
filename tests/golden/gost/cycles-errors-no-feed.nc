A canned cycle needs a feed rate for its working feed (NC4001)
%
N1 G90 G00 X0 Y0 Z10. S500 M03 (NO F PROGRAMMED)
N2 G81 X10. Y10. Z-5. R2. (NC4001)
N3 G80 M05
N4 M30
