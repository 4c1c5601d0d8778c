; NC-110 §2.8.12.3 (seed lines 4516-4537), decision 55: G74 moves like G72 but without
; the radius correction and stores nominal minus measured (E = Pt - Pm), in the order
; the axes are written. Profile cycle-probe-g74; the tool T8.8 (radius 5, ignored)
; starts at 0 0 0.
; N2: G74 X100.2 E41: rapid to X90.2, feed to the contact X100.15 (no radius), rapid
;   back to X0; E41 = 100.2 - 100.15 = 0.05.
; N4: G74 Z-50 E35 toward -Z: rapid to Z-40, contact Z-50.3, back to Z0; E35 =
;   -50 - (-50.3) = 0.3 (a short tool touches late: the wear check of §2.13.10 tests
;   E35 > 0.2).
; N6: the list has run out: G74 Z10 Y20 X30 E36 touches the nominal point: E36 = E37 =
;   E38 = 0. Path from (0,0,0), 37.4166 long: rapid to 27.4166 along it
;   (21.9822, 14.6548, 7.3274), probe to (30,20,10), back to the start.
N1 T8.8 M6
N2 G74 X100.2 E41
N3 (DIS,E41)
N4 G74 Z-50 E35
N5 (DIS,E35)
N6 G74 Z10 Y20 X30 E36
N7 (DIS,E36," ",E37," ",E38)
