; Protected zones DSA/ASC/DSC (NC-110 §2.13.5.5, seed lines 9507-9556); decision 35: a
; zone is the open rectangle of two axes (touching its edge is allowed), taken from the
; current origin when it is defined (stored on the machine); active zones are checked
; before every move, canned-cycle moves included (NC4060).
; Checks:
; - zone 1 = X-10..10 Y-10..10 from the temporary origin X100 Y100 (machine 90..110);
;   after (UAO,0) the moves to its corner X90 Y90 and along its edges are allowed;
; - the zone is not rotated: under (URT,90) G0 X110 Y-90 goes to X90 Y110, along the
;   edge Y110: allowed;
; - (DSA,E1,...) with E1 = 1 (BY) and LR parameters redefines the active zone 1 as
;   X-5..5 Y-5..5: from now on the old square is free (G0 X100 Y100);
; - (DSC,1): the move through the new square is allowed;
; - zone 2 = X20..40 Z-100..-5: G81 at X30 to Z-4 stays above it (allowed); the hole to
;   Z-6 would enter it: NC4060 before the cycle moves.
F100
(UOT,0,X100,Y100)
(DSA,1,X-10 X10,Y10 Y-10)
(ASC,1)
(UAO,0)
G0 X90 Y90
G0 X90 Y110
G0 X110 Y110
(URT,90)
G0 X110 Y-90
(URT,0)
E1=1
E30=-5
E31=5
(DSA,E1,XE30 XE31,YE30 YE31)
G0 X100 Y100
(DSC,1)
G0 X0 Y0
(DSA,2,X20 X40,Z-100 Z-5)
(ASC,2)
G81 R2 Z-4
X30
X30 Z-6
