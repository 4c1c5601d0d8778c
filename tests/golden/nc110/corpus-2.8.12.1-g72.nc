; Copy of corpus part2/2.8.12.1-G72-example.nc (NC-110 §2.8.12.1, seed lines 4466-4480):
; "G72 X100 Y50 E32: E32 and E33 receive the values computed for X and Y". The
; annotation after the block is moved here.
; Added: N1 T9.9 M6 makes the probe's corrector (radius 2) active; the contact comes
; from profile cycle-probe-corpus-g72: machine X100.2 Y50.1 (on the path, 0.2236 past
; the nominal point). The tool starts at 0 0 0.
; Checks (decision 55): the path toward (100,50) is 111.8034 long: rapid to Qa 10
; before the nominal point (91.0557, 45.5279), feed until the probe's centre is its
; radius before the contact (98.4111, 49.2056), rapid back to (0,0); E32 = 100.2 (X),
; E33 = 50.1 (Y).
N1 T9.9 M6
G72 X100 Y50 E32
N3 (DIS,E32," ",E33)
