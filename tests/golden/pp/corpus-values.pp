The value-notation and spacing examples of the manual (seed 003, sections 2.1.2 a-c
and f), each word in a block of its own. Expect: F 1.4 = feed 1.4, S 35 = spindle 35;
X 3620 = 3620 mm (no decimal point: whole millimetres); X 36.12, X 0.2, X 384. = 384,
X .12 = 0.12; X36.12 and X  36.12 are both 36.12 (spaces may stand between address
and value).
%4
N1 G1 F 1.4     S 35 M03
N2 X 3620
N3 X 36.12
N4 X 0.2
N5 X 384.
N6 X .12
N7 X36.12
N8 X  36.12
N9 M30
