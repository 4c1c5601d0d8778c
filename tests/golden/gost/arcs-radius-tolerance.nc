arcs-radius-tolerance: end radius within the arc tolerance (0.002 mm) of the start radius is accepted (GOST 20999 §4.3, ncc decision 22)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0, centre 0 0, start radius 10)
N2 G03 X0 Y10.001 I-10. J0 F100. (end radius 10.001, 0.001 more)
N3 G00 X10. Y0
N4 G02 X0 Y-9.999 I-10. J0 (end radius 9.999, 0.001 less)
N5 M02
