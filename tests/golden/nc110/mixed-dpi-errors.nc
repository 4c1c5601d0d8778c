; DPI while a canned cycle or cutter radius compensation is active (NC-110 §2.13.5.1,
; seed lines 9389-9395); decision 32: NC4064 at run time (ncc check's dry run).
; Checks: after G81 (a cycle stored, decision 51), (DPI,Z,X) is NC4064 naming the
; canned cycle; after G80 and G41, (DPI,Z,X) is NC4064 naming the compensation; after
; G40 it is allowed.
F100
G81 R2 Z-5
(DPI,Z,X)
G80
G41 G1 X10
(DPI,Z,X)
G40 G0 X0
(DPI,Z,X)
