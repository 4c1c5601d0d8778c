; Copy of corpus part4/2.13.1.7-RQO-example.nc (NC-110 §2.13.1.7, seed lines 8167-8168
; and 15641), run twice: with origin 3 not active on X, then active. The annotation
; after " - " is dropped; E31 = 0.254 (mm) and the UAO blocks around it are added.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; origin 3 = X2 Y1 B45 in inches.
; Checks (decision 31): RQO adds E31 to X of origin 3 in the run's copy of the origins
; table, in that origin's unit (0.254 mm = 0.01 inch, L8179), not scaled (L8182).
; First (origin 1 active): nothing moves, no origin event; (UAO,3) then gives
; X = 2.01 in = 51.054 mm, Y 25.4, B 45, Z stays on origin 1 (origin 3 has no Z).
; Second (origin 3 active on X, X scaled by 2): the origin moves at once to
; X = 2.02 in = 51.308 mm; the scale does not act on the correction.
(UAO,1)
E31=0.254
(RQO,3,XE31)
(UAO,3)
(SCF,2,X)
(RQO,3,XE31)
(SCF)
