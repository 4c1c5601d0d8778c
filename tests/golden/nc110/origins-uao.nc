; UAO (NC-110 §2.13.1.1, seed lines 7850-7897) without axis operands; decision 30.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; origin 2 = X300 Y-100 (X and Y
; only); origin 3 = X2 Y1 B45 in inches; origin 0 is zero on every axis.
; Checks:
; - (UAO,1) takes every axis origin 1 declares: origin X100 Y200 Z-50 B10; G0 Z0 moves
;   Z only: X-100 Y-200 Z0 B-10 (the tool's X Y B at machine zero);
; - (UAO,2) takes X and Y of origin 2 and leaves Z and B on origin 1: G0 X0 Y0 goes to
;   machine X300 Y-100, Z stays at 0 from origin 1;
; - (UAO,E10) with E10 = 3 (an IN parameter) takes origin 3, converted from inches:
;   X50.8 Y25.4 B45; Z still on origin 1;
; - under G70 the origin event is in inches (X2 Y1 Z-1.9685), B in degrees;
; - (UAO,0) selects origin 0 on every axis: the tool shows its machine position.
(UAO,1)
G0 Z0
(UAO,2)
G0 X0 Y0
E10=3
(UAO,E10)
G0 X0 Y0 B0
G70
(UAO,3)
G71
(UAO,0)
G0 Z10
