; NC-110 §2.13.9 (seed lines 9877-9881: "if the probe does not switch before the safety
; point, it returns to the start of the measurement and «Нет касания щупа» is shown"),
; decision 55: no contact is NC4070 and the E parameters keep their values.
; Profile cycle-probe-none (Qa 10, Qs 12, no probe radius; the tool starts at 0 0 0).
; N2 ("none"): rapid to X90, feed to the safety point X112 without contact, rapid back
;   to X0; NC4070 between X90 Y0 Z0 and X112 Y0 Z0; `ncc run` stops here (E40 stays 7).
; With `ncc check` (the .check.out) every block is tried:
; N3: contact X112.5 lies past the safety point X112: NC4070.
; N4: contact X89.5 lies before the approach point X90: NC4070.
; N5 ("none"): G73 r50 from (0,0): the first probe, rapid to (40,0), feed to (62,0)
;   without contact, back: NC4070 between X40 Y0 Z0 and X62 Y0 Z0.
N1 E40=7
N2 G72 X100 E40
N3 G72 X100 E40
N4 G72 X100 E40
N5 G73 r50 E41
N6 (DIS,E40)
