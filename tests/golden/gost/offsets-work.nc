offsets-work: G54-G59 select preset offsets 1-6 of the profile (GOST 20999 Table 5); the same physical point, machine X110 Y60 Z-20, in each system
%
N1 G00 X110. Y60. Z-20. (power-on - no preset offset, machine coordinates)
N2 G54 X10. Y10. Z0 (offset X100 Y50 Z-20)
N3 G55 X-90. Y60. Z-20. (offset X200)
N4 G56 X110. Y60. Z-20. (offset zero)
N5 G57 X120. Y70. Z-25. (offset X-10 Y-10 Z5)
N6 G58 X109.5 Y59.75 Z-20.125 (offset X0.5 Y0.25 Z0.125)
N7 G59 X-890. Y60. Z-20. (offset X1000)
N8 G54 G91 X1. (incremental from the current point seen in system 1 - X10 + 1)
N9 M30
