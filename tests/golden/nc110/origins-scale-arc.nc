; SCF with arcs (NC-110 §2.13.1.6); decision 28: unequal scales on the plane's two axes
; with an arc are an error (the arc would be an ellipse, NC4058); a scale on an axis
; outside the plane is allowed.
; Checks:
; - (SCF,2,Z): the XY arc G2 X0 Y-10 about (0,0) keeps radius 10, sweep 90; Z5 of the
;   next move is Z10;
; - (SCF,3,X,Y): equal scales: G0 X0 Y-10 goes to Y-30, and G3 X10 Y0 about (0,0)
;   runs to X30 Y0, radius 30, sweep 90;
; - G19 with (SCF,2,X): the plane YZ is not scaled: G2 Y10 Z0 about Y0 Z0 (I and J are
;   the plane's abscissa and ordinate, decision 39) from Y0 Z10 runs clockwise, radius
;   10, sweep 90;
; - G17 with (SCF,2,X): G0 X10 Y0 goes to X20; the arc G2 X0 Y-10 about (0,0) is
;   NC4058 at the block, before the move.
F100
G0 X10 Y0
(SCF,2,Z)
G2 X0 Y-10 I0 J0
G1 Z5
(SCF,3,X,Y)
G0 X0 Y-10
G3 X10 Y0 I0 J0
(SCF,2,X)
G19
G0 X0 Y0 Z10
G2 Y10 Z0 I0 J0
G17
G0 X10 Y0
G2 X0 Y-10 I0 J0
