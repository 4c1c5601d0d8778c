; NC-110 §2.8.12.1 ("the absolute position of the measured point on every coordinate of
; the block"), decisions 28-29 and 55 with a rotation (§2.13.1.5): G72 X100 programs a
; nominal point in the program's frame, so the value stored for X is in that frame too.
; Profile cycle-probe-origin (one contact given on machine X, so N2 uses the list up).
; N1-N2: G72 X100 E40 at no rotation: E40 = 109.7 (the contact, origin 0).
; N4-N5: rotation 90 degrees; from program (0,0) toward program X100: the machine goes
;   along +Y to (0,100); the list has run out, so the probe touches the nominal point,
;   and E41 must be 100 (program X), not the machine X 0 of the contact.
N1 G X0 Y0
N2 G72 X100 E40
N3 (DIS,E40)
N4 (URT,90)
N5 G72 X100 E41
N6 (DIS,E41)
