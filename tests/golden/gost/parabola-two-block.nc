parabola-two-block: three-point parabola in two blocks, intermediate point then end point (GOST 20999 §4.4.2, Appendix 5, reference S-9.6)
%
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X5. Y5. F100. (block 1, the intermediate point P1 5 5 0)
N3 X10. Y0 (block 2, the end point P2 10 0 0, control 2 P1 - P0/2 - P2/2 = 5 10 0)
N4 G00 X0 Y0 (back to P0)
N5 G91 G06 X5. Y5. (G91 block 1, P1 - P0)
N6 X5. Y-5. (G91 block 2, P2 - P1 is measured from P1)
N7 M02
