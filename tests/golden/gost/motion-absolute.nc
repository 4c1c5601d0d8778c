motion-absolute: G00/G01 under G90, GOST 20999 Appendix 2 (X = x1, Y = y1, Z = z1); words not written keep their coordinate
%
N1 G90 G00 X10. Y20. Z30. (G00 to the absolute point 10 20 30)
N2 G01 X15. F200. (G01, Y and Z not written keep 20 and 30)
N3 Y-5.5 Z0 (G01 is modal, X keeps 15)
N4 G00 X0 Y0 (G00, Z keeps 0)
N5 X-1.25 Z2.5 (G00 is modal)
N6 G01 Y3 (G01 again, Y3 without a point is the integer 3)
N7 X0.001 Y-0.001 (smallest step of format X+053)
N8 M02
