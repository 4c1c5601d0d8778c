; Copy of corpus part4/2.13.5.3-DLO-example.nc (NC-110 §2.13.5.3, Fig. 2.132, seed lines
; 9467-9470). The elision lines are replaced by moves; (UAO,1) is added first.
; Profile frame-limits: origin 1 = X100 Y50; machine travel X -500..500, Y -400..400.
; Checks (decision 34): the working field is taken from the current origin (origin 1):
; X -300..300 (machine -200..400), then Y -200..200; X keeps its limits. Moves to the
; limits are allowed; G0 Y-201 leaves the field: NC4059 before the move.
(UAO,1)
(DLO,X-300 X300)
G0 X300 Y0
G0 X-300
(DLO,Y-200 Y200)
G0 X300 Y-200
G0 Y-201
