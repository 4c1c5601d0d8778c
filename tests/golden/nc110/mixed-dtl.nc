; DTL (NC-110 §2.13.5.2, seed lines 9397-9430); decision 33: DTL sets the in-position
; tolerance of the listed axes (a trace event, the path does not change); 0 restores the
; machine's; the values are in the active unit (G70/G71).
; Profile frame-tolerance: X tolerance 0.01, drive error 0.5; Z 0.02 and 1.
; Checks:
; - (DTL,X0.3,Z1): X0.3 Z1 (Z exactly the drive error is allowed);
; - (DTL,XE30) with the LR parameter E30 = 0.2: X0.2, Z keeps 1 (no Z in the event);
; - under G70 (DTL,X0.01) is 0.254 mm, shown X0.01 (inches);
; - (DTL,X0,Z0): the machine's X0.01 Z0.02;
; - DTL is allowed under the power-on G27 and while a canned cycle is stored; the moves
;   are not changed by it.
(DTL,X0.3,Z1)
E30=0.2
(DTL,XE30)
G70
(DTL,X0.01)
G71
G81 R2 Z-5
(DTL,X0,Z0)
G80
G0 X10
