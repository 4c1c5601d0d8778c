arcs-center-absolute: with arc_center = absolute, I J K under G90 are the centre's coordinates; under G91 they stay increments from the start (GOST 20999 §4.3.3 allows other NCs)
%
N1 G90 G17 G00 X30. Y10. Z0 (start 30 10)
N2 G02 X20. Y10. I25. J10. F100. (centre 25 10 in absolute coordinates, half circle cw)
N3 G91 G02 X10. Y0 I5. J0 (G91, centre 5 0 from the start 20 10 is 25 10, half circle cw)
N4 G90 G18 G03 X35. Z-5. I30. K-5. (ZX plane, centre Z-5 X30 in absolute coordinates, quarter circle ccw)
N5 M02
