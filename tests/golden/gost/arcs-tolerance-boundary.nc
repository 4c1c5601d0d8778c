arcs-tolerance-boundary: an end radius off by exactly arc_tolerance (0.002 mm) is accepted, 0.003 is not (GOST 20999 §4.3, decision 29)
%
N1 G90 G17 G00 X10. Y0 F100.
N2 G03 X0 Y10.002 I-10. J0 (end radius 10.002 - accepted)
N3 G00 X10. Y0
N4 G03 X0 Y9.998 I-10. J0 (end radius 9.998 - accepted)
N5 G00 X10. Y0
N6 G03 X0 Y10.003 I-10. J0 (end radius 10.003 - NC4003)
N7 M02
