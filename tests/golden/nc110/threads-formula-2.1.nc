; Formula 2.1 for a decreasing pitch (§2.8.1.7 L2629: I <= K^2/(ZK-ZN); decision 42: the
; pitch p(s) = K + I*s/K must stay above zero). K10 over L = 50: K^2/L = 2. ncc check.
; G29: no G27 profile rule.
; N2 I-1.99: the pitch ends at 0.05: accepted.
; N4 I-2 (the formula's equality): the pitch would reach 0 exactly at the end, after
;   infinitely many turns: NC4040 "the pitch of G33 falls to zero 50 into the thread,
;   which is 50 long" at I (14:17).
; N6 I-3: zero at K^2/|I| = 33.3333: NC4040 (16:17).
; N8 increasing pitches have no limit: I+100 accepted.
N0 G29 S100 M3
N1 G0 Z0
N2 G33 Z-50 K10 I-1.99
N3 G0 Z0
N4 G33 Z-50 K10 I-2
N5 G0 Z0
N6 G33 Z-50 K10 I-3
N7 G0 Z0
N8 G33 Z-50 K10 I100
