; Copy of corpus part4/2.13.1.4-MIR-example.nc (NC-110 §2.13.1.4, Fig. 2.112, seed lines
; 8051-8058). The elision lines are replaced by moves that show the mirror state.
; Checks (decision 27, nc110.mirror = "set"): after N24 (MIR,X) the mirror acts from
; the first X move (L8061): G0 Y20 leaves X at 10, G0 X10 Y10 goes to X-10 Y10.
; N42 (MIR,X,Y): X and Y: X-10 Y-10. N84 (MIR,X): X stays mirrored and Y keeps its
; mirror (L8034): X-10 Y-10. N99 (MIR): none: X10 Y10.
; The .toggle variant (profile frame-toggle): N42 turns X back and mirrors Y: X10 Y-10;
; N84 mirrors X again: X-10 Y-10; N99: X10 Y10.
G0 X10 Y10
N24 (MIR,X)
G0 Y20
G0 X10 Y10
N42 (MIR,X,Y)
G0 X10 Y10
N84 (MIR,X)
G0 X10 Y10
N99 (MIR)
G0 X10 Y10
