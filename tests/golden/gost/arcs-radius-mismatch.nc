arcs-radius-mismatch: end radius beyond the arc tolerance (0.002 mm) is NC4003 (GOST 20999 §4.3, Appendix 3, ncc decision 22)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0, centre 0 0, start radius 10)
N2 G03 X0 Y10.003 I-10. J0 F100. (NC4003, end radius 10.003)
N3 G00 X10. Y0
N4 G02 X0 Y-9.997 I-10. J0 (NC4003, end radius 9.997)
N5 G00 X10. Y0
N6 G03 X0 Y12. I-10. J0 (NC4003, end radius 12)
N7 M02
