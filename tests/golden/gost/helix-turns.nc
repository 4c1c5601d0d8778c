helix-turns: the helix parameter chooses the number of turns, the end point stays as programmed (GOST 20999 §4.3.4, ncc decision 23)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0 0)
N2 G03 X10. Y0 Z-10. I-10. J0 K-0.796 F100. (down 10 at 0.796 per radian, 12.563 rad, two full turns)
N3 X0 Y10. Z4.137 I-10. J0 K1. (up 14.137 at 1 per radian, a quarter circle and two turns)
N4 G02 X10. Y0 Z0 I0 J-10. K-0.527 (cw, down 4.137 at 0.527 per radian, a quarter circle and one turn)
N5 M02
