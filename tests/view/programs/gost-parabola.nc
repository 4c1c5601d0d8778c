gost-parabola: ncc view test (GOST 20999): parabolas drawn as chords, arcs by their centre, a tool change and a dwell
%
N1 G90 G17 G00 X0 Y0 Z5. S800 M03 T1 M06
N2 G01 Z-1. F200.
N3 G06 X20. Y10. Z-1. F300. (intermediate point)
N4 X40. Y0 Z-1. (end point)
N5 G03 X40. Y20. I0 J10. (half circle ccw about 40 10)
N6 G01 X0
N7 G02 X0 Y0 I0 J-10. (half circle cw about 0 10)
N8 G00 Z5.
N9 X10. Y30. T2 M06
N10 G01 Z-2. F100.
N11 G04 P2
N12 G06 X30. Y40. Z-2. I10. J20. K-2. (the curve in one block, control point 10 20 -2)
N13 G00 Z5.
N14 M02
