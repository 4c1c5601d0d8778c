; Copy of corpus part4/2.13.1.1-UAO-example.nc (NC-110 §2.13.1.1, seed lines 7873-7888
; and 15535-15540). The manual's annotations after " - " are dropped; its elision lines
; "........" are replaced by the move G0 X10 Y10 Z10 B5 (the first) and G0 Z10 (the
; second) so the trace shows which origin each axis uses. Corrected: (UAO,O) has the
; Latin letter O for the digit 0 (both renderings); see
; corpus-2.13.1.2-UOT-example-as-printed for the diagnostic of the printed form.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10, 2 = X300 Y-100 (X Y only),
; 3 = X2 Y1 B45 inch (X50.8 Y25.4 B45 mm).
; Checks (decision 30): (UAO,1) takes every axis origin 1 declares: X100 Y200 Z-50 B10;
; (UAO,2,X,Y) moves X and Y to origin 2, (UAO,3,B) B to origin 3, Z stays on origin 1:
; origin X300 Y-100 Z-50 B45, and the same move goes to machine X310 Y-90 Z-40 B50;
; (UAO,0) selects origin 0 (all zero) on every axis: X310 Y-90 B50 stay, Z goes to 10.
(UAO,1)
G0 X10 Y10 Z10 B5
(UAO,2,X,Y)
(UAO,3,B)
G0 X10 Y10 Z10 B5
(UAO,0)
G0 Z10
