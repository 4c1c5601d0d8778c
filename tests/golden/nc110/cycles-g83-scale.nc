; NC-110 §2.8.9.2 with a scale (§2.13.1.6), decisions 28 and 53: the levels, the depth
; and the peck I are lengths of the program and scale with it (as ncc does), but the
; re-approach "1 mm above the depth reached" is the machine's clearance, like the G70
; case (cycles-g83-inch): it stays 1 mm. The tool starts at 0 0 0.
; Expected with (SCF,2): hole X10 at X20: rapid to X20, rapid to R 4, feed to -6 (peck
; 10), rapid 4, rapid to -5 (1 mm above -6, not 2), feed to -15, rapid 4, rapid to -14,
; feed to the bottom -20, rapid to 4.
S500 F100 M3
(SCF,2)
G83 R2 Z-10 I5 K1
X10
G80
(SCF)
