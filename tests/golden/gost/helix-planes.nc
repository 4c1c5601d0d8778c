helix-planes: helices in G18 (lead J along Y) and G19 (lead I along X), travel per radian (GOST 20999 §4.3.4, reference S-9.2)
%
N1 G90 G18 G00 X0 Y0 Z10. (ZX plane, start Z10 X0)
N2 G02 X0 Y3. Z-10. I0 K-10. J0.955 F100. (half circle cw about Z0 X0, Y up 3, J = 3/pi)
N3 G19 G00 X0 Y10. Z0 (YZ plane, start Y10 Z0)
N4 G03 X2. Y0 Z10. J-10. K0 I1.273 (quarter circle ccw about Y0 Z0, X up 2, I = 4/pi)
N5 M02
