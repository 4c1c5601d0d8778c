; UIO (NC-110 §2.13.1.3, seed lines 7974-8029); decision 26: each UIO shifts the current
; origin by its values, until UAO or RESET.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10.
; Checks:
; - (UOT,1,X10) gives X110; (UIO,X5,Y-5) adds to it: X115 Y-5; (UIO,X5) again: X120;
; - under G70 the values are inches (L8028): (UIO,Y1) adds 25.4 mm: Y20.4, the event in
;   inches X4.7244 Y0.8031;
; - (UAO,1) cancels the shifts on the axes origin 1 declares: X100 Y200 Z-50 B10;
; - (UIO,Z10) then (UIO,XE30) with the LR parameter E30 = 2.5: Z-40, X102.5;
; - (UAO,0) cancels all: origin 0.
(UOT,1,X10)
(UIO,X5,Y-5)
(UIO,X5)
G70
(UIO,Y1)
G71
(UAO,1)
(UIO,Z10)
E30=2.5
(UIO,XE30)
(UAO,0)
