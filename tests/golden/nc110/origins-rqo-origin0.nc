; RQO on origin 0 when the profile does not declare origin 0 (NC-110 §2.13.1.7,
; §2.13.1.1: "(UAO,0) activates origin 0 for all axes"); decisions 25, 30, 31.
; Profile frame-origins: origin 0 is not declared (0 on every axis); origin 1 = X100
; Y200 Z-50 B10.
; Checks: (RQO,0,X0.5) while origin 1 is active moves nothing; (UAO,0) then selects
; origin 0 on every axis: X0.5 Y0 Z0 B0 (the correction does not make origin 0 an
; origin of X alone); G0 Z0 shows the tool, at machine zero, at X-0.5 Y0 Z0 B0.
(UAO,1)
(RQO,0,X0.5)
(UAO,0)
G0 Z0
