; Copy of corpus part1/1.2.35-rqo-origin-requalify.nc (NC-110 §1.2.35, seed line 943;
; the rule is §2.13.1.7, lines 8144-8182). Corrected: the manual prints (RQO,O,XE35)
; with the Latin letter O where the origin number 0 is meant (both renderings; the
; as-printed copy is corpus-1.2.35-rqo-origin-requalify-as-printed). Added: E35 = 0.5
; (the manual's "difference between the measured and the theoretical size") and moves.
; Checks (decision 31): RQO adds 0.5 to X of origin 0 in the run's copy of the origins
; table; origin 0 is active on X, so it moves at once (origin X0.5). The tool does not
; move: seen from the new origin it stands at X9.5, where G0 Y20, which does not write
; X, keeps it (decision 29); G0 X10 then goes to machine X10.5. The correction stays for
; the rest of the run: (UOT,0,X5) adds 5 to it (X5.5), and the RESET of M30 (decision
; 25) selects origin 0 again: X0.5 Y0 Z0, not X0.
E35=0.5
G0 X10 Y10
(RQO,0,XE35)
G0 Y20
G0 X10
(UOT,0,X5)
M30
