arcs-xy: G02/G03 in the XY plane (G17, centre I J), GOST 20999 §4.3 and Appendix 3, under G90
%
N1 G90 G17 G00 X10. Y0 Z-2. (start 10 0, Z is the perpendicular axis and stays -2)
N2 G03 X0 Y10. I-10. J0 F100. (quarter circle ccw about 0 0)
N3 X0 Y-10. I0 J-10. (G03 modal, half circle ccw)
N4 G02 X10. Y0 I0 J10. (three-quarter circle cw)
N5 G02 X10. I-10. J0 (Y not written keeps 0, end = start, full circle cw)
N6 G03 X10. Y0 I-10. (J not written counts as 0, full circle ccw)
N7 G03 X20. I5. (half circle ccw about 15 0, radius 5)
N8 M02
