; SCF with an arc given by radius (NC-110 §2.13.1.6, §2.8.1.4); decision 28.
; Checks: with (SCF,1.5,Y) the plane XY has the scales 1 and 1.5: G2 X20 Y0 R10 is
; NC4058 (found by the dry run of ncc check) at line 8; G18 then makes the plane ZX,
; both unscaled, and its arc G2 Z10 X10 R10 has no error.
F100
(SCF,1.5,Y)
G0 X0 Y0 Z0
G2 X20 Y0 R10
G18
G2 Z10 X10 R10
G0 Z0
