; system-value-ucv: UCV, what the screen shows for the axes: 0 computed values, 1 the
; encoders, 2 the positioning errors (Table 3.3 L11291-11298), 3 the remaining path
; (§2.10.10 L5347-5348 "after the command UCV=3"); decision 16. UCV=3 is fine; UCV=4
; is NC4048 ("it is 0, 1, 2 or 3"), found by the compiler at the value (7:5).
UCV=2
UCV=3
UCV=4
