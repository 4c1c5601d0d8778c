; Copy of corpus part1/1.2.33-g72-measure-point.nc (NC-110 §1.2.33, seed lines 880-883):
; "G 72 Z200 X50 E32: E32 and E33 receive the values computed for Z and X" (the blank
; inside the G word is as printed). Added: N1 T9.9 M6 (probe radius 2) and the DIS
; block; the contact comes from profile cycle-probe-corpus-1.2.33: machine Z199.6 X50.1.
; Checks (decision 55, results in the written order): the path from 0 0 0 toward
; (X50, Z200) is 206.1553 long: rapid to (47.5746, 0, 190.2986), feed until the probe's
; centre is its radius before the contact's projection (49.4267, 0, 197.7068), rapid
; back to 0 0 0; E32 = 199.6 (Z), E33 = 50.1 (X).
N1 T9.9 M6
G 72 Z200 X50 E32
N3 (DIS,E32," ",E33)
