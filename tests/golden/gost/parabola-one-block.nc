parabola-one-block: one-block parabola, I J K are the coordinates of the tangent intersection, absolute under G90, from the start under G91 (GOST 20999 §4.4.3, ncc decision 24)
%
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X10. Y0 I5. J10. F100. (the S-9.6 example, end 10 0 0, tangents meet at 5 10, K not written is the start's Z)
N3 G00 X20. Y0 Z2. (start 20 0 2)
N4 G06 X30. I25. J10. (Y and Z not written keep 0 and 2, control 25 10 2)
N5 G91 G06 X10. I5. J10. (G91, control 5 10 from the start 30 0 2 is 35 10 2, end 40 0 2)
N6 G90 G06 X50. Y10. I50. (J not written is the start's Y 0, control 50 0 2)
N7 M02
