; UOT (NC-110 §2.13.1.2, seed lines 7899-7942): a temporary origin = absolute origin n
; plus the programmed correction, on the listed axes only.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; 2 = X300 Y-100; 3 = X2 Y1 B45 in.
; Checks:
; - after (UIO,X5,Z5), (UOT,1,X-250,Y-50) gives X100-250 = -150 (the UIO shift on X is
;   replaced), Y200-50 = 150; Z keeps origin 0 + 5 (origin X-150 Y150 Z5);
; - (UOT,3,X,Y5): X with no value is a correction of 0: X50.8, Y25.4+5 = 30.4;
; - (UOT,0,YE30) with the LR parameter E30 = -12.5: Y-12.5;
; - under G70 the correction is in inches (L7942): (UOT,2,X1) gives X300+25.4 mm, shown
;   in inches: X12.811 Y-0.4921 Z0.1969;
; - G0 X0 Y0 Z0 goes to the temporary origin, machine X325.4 Y-12.5 Z5, which (UAO,0)
;   then shows.
(UIO,X5,Z5)
(UOT,1,X-250,Y-50)
(UOT,3,X,Y5)
E30=-12.5
(UOT,0,YE30)
G70
(UOT,2,X1)
G71
G0 X0 Y0 Z0
(UAO,0)
G0 X325.4
