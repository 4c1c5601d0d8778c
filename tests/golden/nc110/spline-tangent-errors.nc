; Spline end conditions that need a direction (decision 43: "the lead-in (lead-out)
; direction at a tangent end"; nc110-motion.md D10: a zero-length lead carrying an imposed
; tangent is an error), and the range of n, ncc check. G29: no G27 profile rule.
; Expected:
;  N3 a zero-length lead-in (the tool already at Q0) with n=1 (tangent at the start):
;     NC4052 "a tangent start needs a lead-in of some length: this block does not move",
;     at the lead-in N3 (14:1), found when the spline is cut at N6.
;  N12 a zero-length lead-out with n=2 (tangent at the end): NC4052 "a tangent end needs
;     a lead-out of some length: this block does not move" (23:1).
;  N20 n = 4: NC3018 "'4' cannot be an end condition 0..3 of (BSP): it must lie between 0
;     and 3" (25:14).
N1 G29 G0 X0 Y0
N2 (BSP,X,Y,1)
N3 G1 X0 Y0 F100
N4 G06 X10 Y10
N5 X20 Y0
N6 G1 G40 X30 Y0
N7 (ESP)
N8 (BSP,X,Y,2)
N9 G1 X40 Y0
N10 G06 X50 Y10
N11 X60 Y0
N12 G1 G40 X60 Y0
N13 (ESP)
N20 (BSP,X,Y,4)
