; MIR (NC-110 §2.13.1.4, seed lines 8031-8068); decisions 27 and 28: the mirror is about
; the current origin; a mirror on one axis of the plane turns arcs the other way, on
; both axes (or an axis outside the plane) it does not. Arcs by centre (I J).
; Checks:
; - temporary origin X50: G0 X10 Y0 is machine X60; after (MIR,X) X-10 (machine 40);
; - (MIR,X): G2 X0 Y10 about (0,0) from (10,0), clockwise sweep 270 in the program, is
;   counter-clockwise from X-10 Y0 to X0 Y10 about X0 Y0, sweep 270;
; - (MIR,X,Y): the same G2 runs clockwise from X-10 Y0 to X0 Y-10, sweep 270;
; - (MIR) then (MIR,Y): G3 X0 Y10 from (10,0), counter-clockwise 90 in the program,
;   runs clockwise to X0 Y-10, sweep 90; adding (MIR,Z) mirrors Z (Z5 is Z-5) and the
;   arc still runs clockwise;
; - (MIR,X) then (UAO,0): the tool mirrored to X-10 about X50 is at machine X40.
F100
(UOT,0,X50)
G0 X10 Y0
(MIR,X)
G0 X10 Y0
G2 X0 Y10 I0 J0
G0 X10 Y0
(MIR,X,Y)
G2 X0 Y10 I0 J0
(MIR)
(MIR,Y)
G0 X10 Y0
G3 X0 Y10 I0 J0
(MIR,Z)
G0 X10 Y0 Z5
G3 X0 Y10 I0 J0
G0 X10 Y0 Z0
(MIR)
(MIR,X)
G0 X10 Y0 Z0
(UAO,0)
G0 Y0
