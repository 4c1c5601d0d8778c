; NC-110 §2.8.12.2 (seed lines 4482-4505), decision 55: G73 r probes the hole from its
; centre (where the tool stands) at 0, 120 and 240 degrees in the plane (G17: from +X
; toward +Y): each time a rapid to Qa (10) inside the nominal radius, a feed until the
; probe (radius 2, corrector 9) touches the wall, a rapid back to the centre; it stores
; the centre's abscissa, ordinate and the radius from its E word on.
; Profile cycle-probe-g73 (the tool starts at 0 0 0).
; N2: G73 r100 E55 against the hole centred X0.5 Y-0.3, radius 100.05:
;   0 deg: rapid to (90,0), probe to (98.5496,0);
;   120 deg: rapid to (-45,77.9423), probe to (-48.7699,84.4719);
;   240 deg: rapid to (-45,-77.9423), probe to (-49.0291,-84.9208);
;   E55 = 0.5, E56 = -0.3, E57 = 100.05.
; N5: the list has run out: G73 r20 E30 from (10,10) finds the nominal hole: probes to
;   18 from the centre: (28,10), (1,25.5885), (1,-5.5885); E30 = 10, E31 = 10, E32 = 20.
N1 T9.9 M6
N2 G73 r100 E55
N3 (DIS,E55," ",E56," ",E57)
N4 G X10 Y10
N5 G73 r20 E30
N6 (DIS,E30," ",E31," ",E32)
