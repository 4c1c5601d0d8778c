helix-per-revolution: with helix_lead_per = revolution the helix parameter is the travel per turn (GOST 20999 §4.3.4, "or per revolution")
%
N1 G90 G17 G00 X10. Y0 Z0 (start 10 0 0)
N2 G03 X-10. Y0 Z5. I-10. J0 K10. F100. (the S-9.5 example, 10 per turn, 5 up is half a turn)
N3 X-10. Y0 Z-1. I10. J0 K-2. (down 6 at 2 per turn, three full turns)
N4 G02 X0 Y10. Z-1.5 I10. J0 K-2. (down 0.5 at 2 per turn, a quarter turn cw)
N5 M02
