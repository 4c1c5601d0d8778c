diag-words-lenient: too few digits for a format without zero suppression, lenient mode (NC2008)
%
N001 G01 X00010000 F1000
N002 X125 (NC2008 - read as X00000125, 0.125)
N003 X-25 Y-1 (NC2008 - read as -0.025, Y+053 omits leading zeros anyway)
N004 M30
