; Copy of corpus part4/2.13.1.2-UOT-example.nc (NC-110 §2.13.1.2, seed lines 7919-7936
; and 15551-15556). The manual's annotations after " - " and its list numbers "1)" "2)"
; are dropped; its elision lines are replaced by the move G0 X10 Y10 Z10 B5 (and G0 Z10
; at the end). Corrected: (UAO,O) and (UOT,O,...) have the Latin letter O for the
; digit 0 (both renderings; the printed form is corpus-2.13.1.2-UOT-example-as-printed).
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; origin 0 is zero.
; Checks (§2.13.1.2): (UAO,0): origin 0 on every axis; (UOT,0,X100,Y100): X and Y of
; origin 0 plus 100: origin X100 Y100, Z and B unchanged; (UOT,1,X-250,Y-50): X and Y
; of origin 1 corrected: X100-250 = -150, Y200-50 = 150, Z and B keep origin 0 (not
; origin 1's Z-50 B10); (UAO,0) cancels the temporary origin: the tool stays at machine
; X-140 Y160 B5, Z goes to 10.
(UAO,0)
G0 X10 Y10 Z10 B5
(UOT,0,X100,Y100)
G0 X10 Y10 Z10 B5
(UOT,1,X-250,Y-50)
G0 X10 Y10 Z10 B5
(UAO,0)
G0 Z10
