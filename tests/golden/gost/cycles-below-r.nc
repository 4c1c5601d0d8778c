cycles-below-r: a cycle that starts on the work side of R first rapids up to R, which is then the initial level (decision 34)
%
N1 G90 G17 G00 X0 Y0 Z0 S500 M03
N2 G81 X10. Y0 Z-5. R2. F100. (starts below R - up to R first, then the hole)
N3 X20. (the initial level is now R)
N4 G80 M02
