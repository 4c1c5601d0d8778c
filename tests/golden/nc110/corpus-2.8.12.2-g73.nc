; Copy of corpus part2/2.8.12.2-G73-example.nc (NC-110 §2.8.12.2, seed lines 4490-4505):
; "G73 r100 E55: E55, E56 and E57 receive the abscissa, the ordinate and the radius of
; the circle". The annotation after the block is moved here.
; The hole comes from profile cycle-probe-corpus-g73: centre machine X0.02 Y-0.01,
; radius 100.03; no corrector is active (probe radius 0); the tool stands at 0 0 0, the
; nominal centre. Added: the DIS block shows the results.
; Checks (decision 55): three probes from the centre at 0, 120, 240 degrees: rapid to
; 90 from it, feed to the wall: (100.05,0), (-50.0057,86.6124), (-50.0143,-86.6274),
; rapid back each time; E55 = 0.02, E56 = -0.01, E57 = 100.03.
G73 r100 E55
N2 (DIS,E55," ",E56," ",E57)
