arcs-centre-errors: an arc needs its centre (NC4004) and a radius above zero (NC4005), GOST 20999 §4.3.2
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0)
N2 G03 X0 Y10. F100. (NC4004, neither I nor J in G17)
N3 G18 G02 X0 Z10. (NC4004, neither K nor I in G18)
N4 G19 G03 Y5. Z5. (NC4004, neither J nor K in G19)
N5 G17 G00 X10. Y0 Z0 (back to 10 0)
N6 G02 X0 Y10. I0 J0 (NC4005, the centre is the start point)
N7 M02
