; Protected zones and arcs (NC-110 §2.13.5.5); decision 35: the whole path of an arc is
; checked before it starts.
; Checks: zone 2 = X-10..10 Y-10..10; the half circle G3 from X25 Y15 about X25 Y0,
; radius 15, reaches X10: it touches the zone's edge, allowed; with radius 16 it would
; reach X9, inside the zone, although both ends and the chord are outside: NC4060.
F100
G0 X25 Y15
(DSA,2,X-10 X10,Y-10 Y10)
(ASC,2)
G3 X25 Y-15 I25 J0
G0 X25 Y16
G3 X25 Y-16 I25 J0
