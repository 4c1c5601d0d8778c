; The NC-110 frame (§2.13.1, seed lines 7843-8182); decisions 28 and 29: a programmed
; point is scaled (SCF), mirrored (MIR), rotated counter-clockwise in the plane about the
; current origin (URT), then moved to the origin; the trace shows it from the origin.
; Arc centres and canned-cycle positions and levels are mapped the same way; G79 is not.
; Checks (origin X100 Y50 from (UOT,0,X100,Y50) throughout):
; - scale 2 on X Y Z, mirror X, rotation 90: G0 X10 Y5 Z3 is (20,10,6), mirrored
;   (-20,10,6), rotated X-10 Y-20 Z6; G1 X20 (Y stays 5): X-10 Y-40;
; - G2 X30 Y15 about (20,15), clockwise 270, radius 10: counter-clockwise (one mirror)
;   about X-30 Y-40 to X-30 Y-60, radius 20, sweep 270; F stays 100;
; - (SCF,2,X) scales X only: G0 X10 Y5 Z10 is (20,5,10), mirrored (-20,5,10), rotated
;   X-5 Y-20 Z10 (rotating before scaling would give X10 Y10; mirroring after rotating
;   X5 Y10);
; - (MIR) and scale 2 on X Y Z: G81 R2 Z-5 at X5 Y0 drills at (10,0) rotated, X0 Y10,
;   from R1 4 to Z-10, back to 4; the rapid to the hole keeps the tool where it is,
;   machine Z10 (reached while Z was not scaled);
; - G79 X0 Y0 is machine zero, X-100 Y-50 from the origin; G0 X0 Y0 is mapped again.
F100
(UOT,0,X100,Y50)
(SCF,2,X,Y,Z)
(MIR,X)
(URT,90)
G0 X10 Y5 Z3
G1 X20
G2 X30 Y15 I20 J15
G0 Z10
(SCF,2,X)
G0 X10 Y5 Z10
(MIR)
(SCF,2,X,Y,Z)
G81 R2 Z-5
X5 Y0
G80
G79 X0 Y0
G0 X0 Y0
