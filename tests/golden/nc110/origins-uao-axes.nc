; UAO with axis operands (NC-110 §2.13.1.1, seed lines 7850-7897); decision 30.
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10; 2 = X300 Y-100; 3 = X2 Y1 B45 in.
; Checks: the listed axes take origin n, the others keep theirs; no warning for the
; axis operands (they are the code's operands, not axis words of a move):
; - (UAO,1,X,Z): origin X100 Y0 Z-50 (Y stays on origin 0);
; - (UAO,3,B): B45 (inches do not apply to B), the others unchanged;
; - (UAO,2,Y): Y-100; G0 X0 Y0 Z0 B0 goes to machine X100 Y-100 Z-50 B45;
; - (UAO,0,X,Y,Z,B): origin 0 on the four: the tool shows X100 Y-100 Z-50 B45.
(UAO,1,X,Z)
(UAO,3,B)
(UAO,2,Y)
G0 X0 Y0 Z0 B0
(UAO,0,X,Y,Z,B)
G0 Z-50
