parabola-incremental: with parabola_ijk = incremental, I J K of a one-block parabola count from the start point under G90 and G91 (GOST 20999 §4.4.3)
%
N1 G90 G17 G00 X20. Y0 Z2. (start 20 0 2)
N2 G06 X30. Y0 I5. J10. F100. (G90, control start + 5 10 0 = 25 10 2)
N3 G91 G06 X10. I5. J10. (G91, control 35 10 2, end 40 0 2)
N4 G90 G06 X50. Y10. I10. (J and K not written are 0, control 50 0 2)
N5 M02
