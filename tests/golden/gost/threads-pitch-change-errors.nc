threads-pitch-change-errors: the G34/G35 pitch change is positive (NC4039) and G35 must not bring the pitch to zero within the thread (NC4040), GOST 20999 §7.4
%
N1 G90 G00 X10. Z5. S500 M03
N2 G34 Z-20. K1.5 Q-0.05 (NC4039, a negative change)
N3 G00 Z5.
N4 G35 Z-20. K1.5 Q0.1 (NC4040, the pitch reaches zero after 1.5x1.5/0.2 = 11.25 of 25 mm)
N5 G00 Z5.
N6 G35 Z-20. K1.5 Q0.04 (accepted, zero only after 1.5x1.5/0.08 = 28.125 mm)
N7 M02
