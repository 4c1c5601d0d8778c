; MIR with arcs given by radius (NC-110 §2.13.1.4, §2.8.1.4); decisions 27 and 39: R+
; gives the arc up to 180 degrees, R- the longer one, and a mirror on one axis of the
; plane turns the arc the other way: the mirrored arc is the mirror image of the
; unmirrored one, with the same sweep.
; Checks (unmirrored, for reference: G3 X20 Y5 R10 from X30 Y15 runs about X30 Y5,
; sweep 90; G2 X20 Y5 R-10 about X30 Y5, sweep 270):
; - (MIR,X): G3 X20 Y5 R10 runs clockwise from X-30 Y15 to X-20 Y5 about X-30 Y5,
;   sweep 90 (not 270);
; - G2 X20 Y5 R-10 runs counter-clockwise about X-30 Y5, sweep 270 (not 90);
; - (MIR,X,Y), an even mirror: G3 X20 Y5 R10 runs counter-clockwise from X-30 Y-15 to
;   X-20 Y-5 about X-30 Y-5, sweep 90.
F100
G0 X30 Y15
G3 X20 Y5 R10
G0 X30 Y15
G2 X20 Y5 R-10
(MIR,X)
G0 X30 Y15
G3 X20 Y5 R10
G0 X30 Y15
G2 X20 Y5 R-10
(MIR,X,Y)
G0 X30 Y15
G3 X20 Y5 R10
G0 X30 Y15
