; Copy of corpus part4/2.13.5.5-DSA-ASC-DSC-example.nc (NC-110 §2.13.5.5, Fig. 2.133,
; seed lines 9547-9555). The elision lines "------------" are replaced by moves.
; Checks (decision 35): zone 1 = X-300..-100 Y-100..100 and zone 2 = X200..450
; Y-50..50 from the current origin (origin 0), written with and without blanks; ASC
; activates both. A zone is an open rectangle: moves to a corner of zone 1, along its
; edge X-100, to a corner of zone 2 and along its edge Y-50 are allowed. N80 (DSC, 1)
; deactivates zone 1: the move to X-200 Y-60 (inside zone 1) is allowed. The move to
; X300 Y0 would cross zone 2: NC4060 before it starts, so N99 is not reached.
N1  (DSA, 1,X-300 X-100, Y-100Y100)
N2  (DSA, 2,X200X450,Y-50Y50)
N3  (ASC, 1)
N4  (ASC, 2)
N5  T1.1 M6
G0 X-100 Y100
G0 X-100 Y-100
G0 X200 Y-50
G0 X450 Y-50
N80 (DSC, 1)
G0 X-200 Y-60
G0 X300 Y0
N99 M30
