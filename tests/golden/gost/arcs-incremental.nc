arcs-incremental: GOST 20999 Appendix 3 and §4.3.3, I J are increments from the start point to the centre under G91 and under G90
%
N1 G90 G17 G00 X20. Y10. Z0 (start P0 20 10)
N2 G91 G02 X5. Y5. I5. J0 F100. (X = x1 - x0, I = xc - x0, centre 25 10, quarter circle cw)
N3 G03 X5. Y-5. I0 J-5. (from 25 15 to 30 10, three-quarter circle ccw)
N4 X0 Y0 I-5. J0 (zero increments, end = start, full circle ccw)
N5 G90 G02 X20. Y10. I-5. J0 (G90, I J still from the start point, centre 25 10, half circle cw)
N6 G91 G03 X6. Y8. I3. J4. (centre 23 14, radius 5, half circle ccw off the axes)
N7 M02
