motion-incremental: G00/G01 under G91, GOST 20999 Appendix 2 (X = x1 - x0, Y = y1 - y0, Z = z1 - z0)
%
N1 G90 G00 X10. Y10. Z10. (start point P0 10 10 10)
N2 G91 G01 X5. Y-2.5 Z-10. F100. (P1 15 7.5 0 written as increments from P0)
N3 X-15. (G91 modal, only X moves, to 0 7.5 0)
N4 G00 Y2.5 Z3. (rapid by increments to 0 10 3)
N5 Z0 (a zero increment, no axis moves)
N6 G90 X1. (back to G90, X1 is absolute)
N7 G91 G01 X0.001 Y-0.001 (smallest increments)
N8 X-0.001 Y0.001 (back to 1 10 3)
N9 M02
