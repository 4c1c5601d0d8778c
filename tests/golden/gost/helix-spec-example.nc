helix-spec-example: the example of the reference S-9.5, a half turn rising 5 mm, K = 5/pi = 1.59155 written as 1.592 (GOST 20999 §4.3.4, Appendix 4)
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0 0)
N2 G03 X-10. Y0 Z5. I-10. J0 K1.592 F100. (K is the travel per radian, 1.592 x pi = 5.0014 fits 5 within the tolerance)
N3 M02
