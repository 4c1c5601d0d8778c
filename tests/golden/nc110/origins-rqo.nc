; RQO (NC-110 §2.13.1.7, seed lines 8144-8182); decision 31: RQO adds to origin n in the
; run's copy of the origins table, in that origin's unit; an active origin moves at once.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; 2 = X300 Y-100; 3 = X2 Y1 B45 in.
; Checks:
; - (UAO,1) then (UIO,X5): X105; (RQO,1,XE30,Z-2) with E30 = 1.5 moves origin 1 to
;   X101.5 Z-52, active on X and Z: X106.5 (the UIO shift stays) Z-52 at once;
; - (RQO,2,Y10): origin 2 is not active, nothing moves; (UAO,2) then gives Y-90;
; - under G70, (RQO,3,X0.5) adds 0.5 inch to origin 3 (stored in inches): (UAO,3)
;   gives X2.5 Y1 (inches), Z on origin 1, -52 mm = -2.0472 in;
; - (UAO,1) cancels the UIO shift but keeps the corrections: X101.5 Y200 Z-52 B10.
(UAO,1)
(UIO,X5)
E30=1.5
(RQO,1,XE30,Z-2)
(RQO,2,Y10)
(UAO,2)
G70
(RQO,3,X0.5)
(UAO,3)
G71
(UAO,1)
