threads-basic: G33 constant-pitch threads, pitch K parallel to Z or I parallel to X in mm per revolution, taper thread with X and Z (GOST 20999 §7.1-7.3)
%
N1 G90 G00 X10. Z5. S500 M03 (spindle turning, S500)
N2 G33 Z-20. K1.5 (cylindrical thread along Z, pitch 1.5)
N3 G00 X12.
N4 Z5.
N5 G33 X14. Z-30. K1.5 (taper thread, X and Z, pitch 1.5 measured along Z)
N6 G00 X10. Z-20.
N7 G33 X30. I2. (thread along X, pitch 2 parallel to X)
N8 X40. I2. (G33 is modal, the pitch is written in every thread block)
N9 M02
