arcs-spec-examples: the three arcs of the reference S-9.4, G17 G90, start 10 0 (GOST 20999 §4.3, Appendix 3)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0)
N2 G03 X0 Y10. I-10. J0 F100. (centre 0 0, r 10, quarter circle ccw)
N3 G00 X10. Y0 (back to 10 0)
N4 G91 G03 X-10. Y10. I-10. J0 (the same arc written in G91)
N5 G90 G00 X10. Y0 (back to 10 0)
N6 G02 X10. Y0 I-10. J0 (end = start, full circle cw about 0 0)
N7 M02
