; Built from the example of NC-110 §2.13.5.1 (seed lines 9383 and 16324; part4 of the corpus lacks
; it): (DPI,X,A), the plane of X and A. Added: an arc in that plane and (DPI,X,Y).
; Checks (decision 32): DPI sets X as the abscissa and A as the ordinate; I and J are
; the centre's abscissa and ordinate (decision 39): G3 from X10 A0 to X0 A10 about
; X0 A0 is counter-clockwise, radius 10, sweep 90, in plane XA; A shows in the trace
; once it has moved. (DPI,X,Y) returns to the XY plane.
F100
G0 X10 A0
(DPI,X,A)
G3 X0 A10 I0 J0
G0 X10
(DPI,X,Y)
