; NC-110 §2.8.9 (the cycle's operands and F are stored), decision 52: a block in an
; active cycle without a position only updates what it writes (here the peck I and F)
; and drills nothing; the next holes use the new values. The tool starts at 0 0 0.
; X10 (I5 K1): XY at Z0, rapid to R2, feed to -3, rapid 2, rapid -2, feed to -6
;   (clipped), rapid 2.
; I3: nothing moves. X20: feed to -1, then from 1 mm above each bottom: -3, -5, -6,
;   each peck followed by a rapid to R1 2.
; F50: only the feed_rate event. X30: as X20, at F50.
S500 F100 M3
G83 R2 Z-6 I5 K1
X10
I3
X20
F50
X30
G80
