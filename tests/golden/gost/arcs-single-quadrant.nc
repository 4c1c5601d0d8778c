arcs-single-quadrant: with arc_single_quadrant an arc in one block must lie in one quadrant (GOST 20999 §4.3.5, NC4006)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0, centre 0 0 below)
N2 G03 X0 Y10. I-10. J0 F100. (quarter circle from axis to axis, allowed)
N3 X-6. Y8. I0 J-10. (inside the second quadrant, allowed)
N4 G02 X0 Y10. I6. J-8. (back cw inside the second quadrant, allowed)
N5 G03 X0 Y-10. I0 J-10. (NC4006, half circle over the -X axis)
N6 G00 X8. Y-6.
N7 G03 X8. Y6. I-8. J6. (NC4006, a short arc over the +X axis)
N8 G00 X10. Y0
N9 G03 X10. Y0 I-10. J0 (NC4006, a full circle)
N10 M02
