arcs-yz: G02/G03 in the YZ plane (G19), axes in the order Y Z, centre J K, seen from +X (GOST 20999 §4.3, Table 5)
%
N1 G90 G19 G00 X-3. Y10. Z0 (start Y10 Z0, X is the perpendicular axis and stays -3)
N2 G03 Y0 Z10. J-10. K0 F100. (quarter circle ccw from +Y towards +Z about Y0 Z0)
N3 G02 Z-10. K-10. (J not written counts as 0, Y keeps 0, half circle cw)
N4 Y10. Z0 J0 K10. (G02 modal, three-quarter circle cw)
N5 G03 Y10. J-10. (end = start, full circle ccw)
N6 Y20. J5. (half circle ccw about Y15 Z0, radius 5)
N7 M02
