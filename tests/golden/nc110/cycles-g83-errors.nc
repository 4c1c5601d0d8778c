; NC-110 §2.8.9.2 (seed lines 3844-3877), decision 53: G83 needs its peck increment I
; (NC4029, at the cycle's block); a peck of 1 mm or less after chip unloading would never
; get deeper, since the tool comes back to 1 mm above the depth reached (NC4069, at the
; hole's block, before the tool moves). J0 is allowed.
; line 11: no I.
; lines 14-15: J0: no error (the hole X10 drills in 7 pecks of 5, each from 1 mm above
;   the last bottom: -3 -7 -11 -15 -19 -23 -25).
; lines 17-18: I5 K.5: pecks 5, 2.5, 1.25, then 0.625 is refused at line 18.
; lines 20-21: I.8 K1: the first peck of 0.8, then the next 0.8 is refused at line 21.
F100 S500 M3
G83 R2 Z-25
X10
G80
G83 R2 Z-25 I5 J0
X10
G80
G83 R2 Z-25 I5 K.5
X20
G80
G83 R2 Z-25 I.8 K1
X30
G80
