; gtl-definitions: the definition forms of §2.11.4-2.11.7 with the values the manual's
; figures give (spec nc110-3 §3.8-3.10, derived there and checked here to 3 decimals),
; read back with FEP, FEL and FEC (§2.12, decision 71: FEL gives the sine and cosine of
; the line's angle and its distance from the zero, positive when the zero lies to the
; line's right; FEC the centre and the signed radius). ARS of the sine is the angle
; where it is within 90 deg.
; Origins and points (§2.11.4, §2.11.5): o1 = X30 Y30 a-20, p5 = o1 X20 Y10 ->
; (52.214, 32.557); p2 = m55 a60 -> (27.5, 47.631).
o1 = X30 Y30 a-20
p5 = o1 X20 Y10
p2 = m55 a60
E30=FEP(5,1)
E31=FEP(5,2)
E32=FEP(2,1)
E33=FEP(2,2)
(DIS,"p5 ",E30," ",E31," p2 ",E32," ",E33)
; Lines through two points (fig. 2.61: 68.199 deg) and tangent from a point to a circle
; (fig. 2.62: to the clockwise circle 46.397 deg, to the counter-clockwise one 0 deg,
; touching at (45, 15): its distance from the zero is 15, the zero lying to its right).
l1 = X40 Y20, X60 Y70
l2 = X10 Y15, I45 J30 r-15
l3 = X10 Y15, I45 J30 r15
E30=ARS(FEL(1,1))
E31=ARS(FEL(2,1))
E32=ARS(FEL(3,1))
E33=FEL(3,3)
(DIS,"2.61 ",E30," 2.62 ",E31," ",E32," ",E33)
; Tangent to a circle at an angle (fig. 2.65: touching at (88.284, 51.716), so its
; distance is -25.858), to two circles (fig. 2.67 crossed: -57.666; fig. 2.68 outer:
; -13.598), and parallel (fig. 2.75, 2.76: 20 to the left, 15 to the right).
l4 = I60 J80 r40, a45
l5 = I25 J35 r-17, I70 J20 r13
l6 = I25 J35 r17, I70 J20 r13
l7 = l4, d20
l8 = l4, d-15
E30=FEL(4,3)
E31=ARS(FEL(5,1))
E32=ARS(FEL(6,1))
E33=FEL(7,3)
E34=FEL(8,3)
(DIS,"2.65 ",E30," 2.67 ",E31," 2.68 ",E32," 2.75 ",E33," 2.76 ",E34)
; Circles: polar centre (fig. 2.83: (60.622, 35)); through three points, both ways
; round (fig. 2.95: r 10 and -10); concentric (fig. 2.97's form: 10 - 4 = 6).
c2 = m70 a30 r15
p10 = X10 Y0
p11 = X0 Y10
p12 = X-10 Y0
c3 = p10, p11, p12
c4 = p12, p11, p10
c5 = c3, d4
E30=FEC(2,1)
E31=FEC(2,2)
E32=FEC(3,3)
E33=FEC(4,3)
E34=FEC(5,3)
(DIS,"2.83 ",E30," ",E31," 2.95 ",E32," ",E33," 2.97 ",E34)
; The storage example (§2.11.2): c1 = l1, l2, r15 about (29.046, 70.259); and example
; 3's c2 = c1, p3, r40, which lands on its helper circle's centre (0, 80): its x shows
; as 1.9e-14, the rounding of the arithmetic.
o2 = X30 Y30 a45
p1 = o2 X15 Y15
p3 = X60 Y30
l11 = p1, p3
l12 = X30 Y50, a45
c1 = l11, l12, r15
c13 = I-65 J0 r55
c14 = I0 J80 r55
p20 = c13, c14
c21 = p20, r-15
p21 = X40 Y80
c22 = c21, p21, r40
E30=FEC(1,1)
E31=FEC(1,2)
E32=FEC(22,1)
E33=FEC(22,2)
(DIS,"c1 ",E30," ",E31," c22 ",E32," ",E33)
M30
