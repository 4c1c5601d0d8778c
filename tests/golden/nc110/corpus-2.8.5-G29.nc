; Corpus copy of part2/2.8.5-G29-point-to-point-example.nc (seed §2.8.5, L3096-3120), run
; with profile motion-tools (tools 4 and 5, correctors 4 and 5 on Z).
; Changed: the typographic quotes of N9 and N20 are ASCII quotes (Table 2.1); the manual's
; annotations after N11, N13, N14, N17 are dropped ("start of point-to-point machining",
; "spindle stop", "change of S, spindle rotation", "stop at the end of the block"); the
; dotted elisions and N22-N24 (elided values "G.. Y..", "Z-..", "X.. Y..") are dropped.
; The manual: point-to-point from N11 (G29); M and S are allowed inside the profile (N13,
; N14); N17 stops at the end of its block with a 2 s dwell (G4, TMR=2 from N16).
; Expected: N10 S800, T4 selected, M06 loads it and corrector 4 (decision 11: length 120.5
; on Z); N11 path point_to_point, M13 (spindle cw + coolant) before the rapid; N12 rapid
; Z-10; N13 line to X75 Y230 at F500, M05 after it (spindle stop, coolant off); N14 S1200
; and M13 before the line to X75 Y0 (bare Y = Y0); N15 CCW about X0 Y0 (I J = 0 0):
; start radius 75, end radius 74.99953 (within 0.01), sweep 160.0011 deg; N16 TMR=2;
; N17 line to X-187 Y-295, then the dwell of 2 s (G94: seconds, decision 45); N18 rapid
; Z5; N19 M05; N20 message "24"; N21 S1200, T5, M06 loads corrector 5 (Z98.25).
N9 (DIS,"ФРЕЗА D=16")
N10 S800 T4.4 M6
N11 G29 G X-235 Y230 M13
N12 Z-10
N13 G1 X75 F500 M5
N14 Y S1200 M13
N15 G3 X-70.477 Y25.65 I J
N16 TMR=2
N17 G1 G4 X-187 Y-295
N18 G Z5
N19 M5
N20 (DIS,"24")
N21 T5.5 M6 S1200
