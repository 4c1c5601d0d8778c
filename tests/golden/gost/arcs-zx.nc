arcs-zx: G02/G03 in the ZX plane (G18), axes in the order Z X, centre K I, seen from +Y (GOST 20999 §4.3, Table 5)
%
N1 G90 G18 G00 X0 Y5. Z10. (start Z10 X0, Y is the perpendicular axis and stays 5)
N2 G03 X10. Z0 I0 K-10. F100. (quarter circle ccw from +Z towards +X about Z0 X0)
N3 G02 X-10. I-10. (K not written counts as 0, Z keeps 0, half circle cw)
N4 X0 Z10. I10. K0 (G02 modal, three-quarter circle cw)
N5 G03 Z10. K-10. (end = start, full circle ccw)
N6 Z20. K5. (half circle ccw about Z15 X0, radius 5)
N7 M02
