; NC-110 §2.8.12.2 ("the hole in the current plane", centre abscissa, ordinate, radius),
; decisions 40 and 55: in G18 the plane is (Z, X), so G73 probes from +Z toward +X and
; stores E40 = the centre's Z, E41 = its X, E42 = the radius. Profile cycle-probe-g18:
; the hole at machine Z1 X2, radius 30; the probe radius is 0; the tool starts at 0 0 0.
; Expected trace of N2: rapid to Z20, probe to Z30.9333; back to 0; rapid to Z-10
;   X17.3205, probe to Z-15.587 X26.9974; back; rapid to Z-10 X-17.3205, probe to
;   Z-13.8838 X-24.0475; back. N3: E40=1 2 30.
N1 G18
N2 G73 r30 E40
N3 (DIS,E40," ",E41," ",E42)
