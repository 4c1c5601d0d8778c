helix-lead-errors: a helix lead that does not fit the travel is NC4007 (GOST 20999 §4.3.4, Appendix 4, ncc decision 23)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0 0)
N2 G03 X-10. Y0 Z5. I-10. J0 K1. F100. (NC4007, lead 1 gives 5 rad, the half circle needs pi)
N3 G00 X10. Y0 Z0
N4 G03 X-10. Y0 Z5. I-10. J0 K1.58 (NC4007, 1.58 x pi = 4.9637, 0.0363 short of 5)
N5 G00 X10. Y0 Z0
N6 G03 X10. Y0 Z-10. I-10. J0 K-0.8 (NC4007, 12.5 rad is not a whole number of turns)
N7 G18 G00 X0 Y0 Z10.
N8 G02 X0 Y3. Z-10. I0 K-10. J1. (NC4007, in G18 the lead is J, 3 rad against pi)
N9 M02
