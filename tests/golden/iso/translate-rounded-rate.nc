(translate-rounded-rate: a CAM program's feed and speed with more decimals than the)
(target writes, rounded to them by at most a hundredth of each: NC4099)
G21 G90 G94
S1234.5678 M03
G01 X10. F369.752387
F100.0004
X20.
G04 P0.12
M30
