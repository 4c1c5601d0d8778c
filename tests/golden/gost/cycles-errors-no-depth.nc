A canned cycle needs the hole bottom (NC4017): the drilling-axis word of a cycle block, not an earlier motion
%
N1 G90 G00 X0 Y0 Z10. S500 M03 (Z10 IS A MOTION, NOT A DEPTH)
N2 G81 X10. Y10. R2. F100. (NO Z IN A CYCLE BLOCK, NC4017 NAMES Z)
N3 G80 G19 (DRILLING AXIS X)
N4 G81 Y20. Z5. R2. (Y AND Z GIVE THE HOLE, NO X, NC4017 NAMES X)
N5 G80 M05
N6 M30
