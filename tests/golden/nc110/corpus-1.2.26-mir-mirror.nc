; Copy of corpus part1/1.2.26-mir-mirror.nc (NC-110 §1.2.26, seed lines 707-711; the
; rule is §2.13.1.4, lines 8031-8068). The manual's elision lines "........." are
; replaced by the same move, G0 X10 Y10, which shows the mirror state in the trace.
; Checks (decision 27, default nc110.mirror = "set"): (MIR,X) mirrors X: X-10 Y10;
; (MIR,Y) adds Y and keeps X ("for undeclared axes the previous MIR remains in force",
; L8034): X-10 Y-10; (MIR,X,Y): X-10 Y-10. A last (MIR) cancels every mirror: X10 Y10.
; The .toggle variant (profile frame-toggle, nc110.mirror = "toggle") turns a mirrored
; axis back: the states are X, XY, then none at (MIR,X,Y) (X10 Y10), then none.
G0 X10 Y10
(MIR,X)
G0 X10 Y10
(MIR,Y)
G0 X10 Y10
(MIR,X,Y)
G0 X10 Y10
(MIR)
G0 X10 Y10
