threads-errors: a thread block needs one pitch word I or K (NC4010) above zero (NC4042), measured along an axis that moves (NC4041), and no F (NC4011), GOST 20999 §7.1, §7.3
%
N1 G90 G00 X10. Z5. S500 M03 (spindle turning)
N2 G33 Z-20. K1.5 F100. (NC4011, F in a thread block)
N3 G00 Z5.
N4 G33 Z-20. (NC4010, no pitch word)
N5 G00 Z5.
N6 G33 Z-20. K-1.5 (NC4042, the pitch must be above zero)
N7 G00 Z5.
N8 G33 Z-20. K0 (NC4042, a zero pitch)
N9 G00 Z5.
N10 G33 Z-20. K1.5 (a good thread block)
N11 Z-25. (NC4010, G33 is modal but the pitch is not)
N12 G00 Z5.
N13 G33 X20. I1.5 K1.5 (NC4010, I and K both)
N14 G00 X10. Z5.
N15 G33 Z-20. I1.5 (NC4041, the pitch is along X, which does not move)
N16 M02
