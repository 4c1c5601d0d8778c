corpus-appendix4-helix: GOST 20999 Appendix 4 (figure 3, corpus-appendix4-linear-circular-composition.txt), block composition G03G17XYZIJK in both columns
%
N1 G90 G17 G00 X20. Y0 Z0 F100. (P0 x0 20 y0 0 z0 0, F set for the feed moves)
N2 G03G17X10.Y10.Z3.142I-10.J0K2. (absolute, X x1, Y y1, Z z2, I xc-x0, J yc-y0, K z3-z0 = 2 per radian, centre 10 0)
N3 G00 X20. Y0 Z0 (back to P0)
N4 G91 (the incremental column)
N5 G03G17X-10.Y10.Z3.142I-10.J0K2. (incremental, X x1-x0, Y y1-y0, Z z2-z0, I J K as in the absolute column)
N6 M02
