; NC-110 §2.13.8-2.13.10 and the §2.15 examples that use them, decisions 80-82. Profile
; tooling: tool 10 (corrector 1: length 75, radius 5, wear 0.1 of at most 0.3, the
; diameter's at most 0.1) has sister 110, which brings corrector 11 (length 80).
; N2: (DPT,5,8,600): the probe now starts 5 mm before the nominal point (N180 rapids to
;   Z-45, not Z-40) at 600 mm/min.
; N180 (§2.15.2.2.1, example 1): contact Z-50.1, E30 = -50 - (-50.1) = 0.1; N190 adds it
;   to corrector 1's length (75.1) and wear (0.2); K alone adds 0. No # needed: E30
;   comes from a measuring cycle.
; N210-N260 (example 2): E30 = 0.05, E31 = 130 - 129.96 = 0.04, doubled to 0.08 (a
;   diameter); length 75.15, radius 5 + 0.08 / 2 = 5.04, wear 0.25 and 0.08.
; N190 and N260 leave the offset in force alone: N270's selection brings 75.15 in.
; N300 (§2.15.1.5 N24): RQP sets the probe's corrector 30 without wear: radius 2 + 0.2 / 2.
; N499 (not in the manual's fragment) takes the tool up from Z-60 first.
; N510-N530 (§2.15.2.2.2): contact Z-50.3, E35 = 0.3 > 0.2, so TOF declares tool 10 unusable; N550 is
;   shown all the same (the label A1 follows N540).
; N560: T10.1 selects sister 110 with its corrector 11: length 80.
; N570: 0.5 of wear on corrector 11, beyond 0.4: tool 110 unusable too.
; N580: T10 has no usable sister left: NC4105, and the run stops. `ncc check` goes on
;   (tooling-requalify.check): N585's selection of tool 10 is not reported again.
N1 T10.1 M6
N2 (DPT,5,8,600)
N170 GX100 Y100
N180 G74 Z-50 E30
N190 (RQU,10,1,ZE30,K)
N200 GX100 Y100
N210 G74 Z-50 E30
N220 G X150
N230 Z-60
N240 G74 X130 E31
N250 E31=E31*2
N260 (RQU,10,1,ZE30,KE31)
N270 T10.1 M6
N300 E34=0.2
N310 # (RQP,30,30,KE34)
N490 T10.1 M6
N499 G Z0
N500 GX100 Y100
N510 G74 Z-50 E35
N520 (BLE,E35,0.2,A1)
N530 (TOF,10)
N540 M00
"A1" N550 (DIS,"TOOL OK")
N560 T10.1 M6
N570 # (RQU,110,11,Z0.5)
N580 T10.1 M6
N585 T10.1 M6
N590 M30
