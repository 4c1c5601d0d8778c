; NC-110 §2.8.12.1, decision 55 with an origin (§2.13.1.2): the contacts are machine
; coordinates; the stored values are coordinates from the active origin, like every
; programmed point. Profile cycle-probe-origin, no corrector (probe radius 0).
; N1: temporary origin at machine X10 Y5.
; N2: G72 X100 E40 from program (-10,-5): nominal machine X110 Y0: rapid to program
;   X90, probe to the contact at machine X109.7 (program 99.7), back to (-10,-5);
;   E40 = 99.7.
; N4: the list has run out: G72 X50 Y20 E41 stores the nominal 50, 20 (program
;   coordinates) although the machine is at X60 Y25 there.
N1 (UOT,0,X10,Y5)
N2 G72 X100 E40
N3 (DIS,E40)
N4 G72 X50 Y20 E41
N5 (DIS,E41," ",E42)
