; G06 splines with the four end conditions (§2.8.1.3, L2118-2240, Fig. 2.3; decision 43):
; a cubic through the lead-in's end Q0 and every G06 point, parameter = chord length, a
; natural end (curvature 0) or a tangent end (the unit direction of the lead-in P->Q0 or
; of the lead-out Qm->P); one spline event per G06 block: the cubic Bezier span ending at
; that block's point, controls Qi + h*Di/3 and Qi+1 - h*Di+1/3. The spline is cut when the
; lead-out comes, so the span events precede the lead-out's event.
; Points: P = X-10 Y-10 (where the lead-in starts), Q0 = X0 Y0, Q1 = X10 Y0, Q2 = X15 Y5,
; Q3 = X15 Y20, lead-out to X15 Y30. Controls computed independently (a tridiagonal
; solve of the first-derivative equations, nc110-motion.md D10), 4 decimals:
; n=0: N4 (3.5147,-0.6667) (7.0294,-1.3333); N5 (12.1005,0.9428) (13.9289,2.8856);
;      N6 (17.2721,9.4853) (16.136,14.7426)
; n=1: N14 (2.357,2.357) (6.7606,-0.6311); N15 (12.2906,0.4463) (13.9992,2.7022);
;      N16 (17.1231,9.8744) (16.0616,14.9372)
; n=2: N24 (3.4924,-0.6616) (6.9848,-1.3232); N25 (12.132,0.9357) (14.0254,2.8638);
;      N26 (17.0674,9.5317) (15,15)
; n=3: N34 (2.357,2.357) (6.7237,-0.629); N35 (12.3167,0.4447) (14.0882,2.6969);
;      N36 (16.9343,9.8855) (15,15)
; F applies along the curve (decision 43): spans n=0 10.1626 + 7.2012 + 15.3125 mm, with
; the rapid (0.06 s), the lead-in 14.1421 mm and the lead-out 10 mm at F100: TIM0 34.15106.
N1 G0 X-10 Y-10
N2 (BSP,X,Y,0)
N3 G1 X0 Y0 F100
N4 G06 X10 Y0
N5 X15 Y5
N6 X15 Y20
N7 G1 G40 X15 Y30
N8 (ESP)
E25 = TIM0
(DIS,E25)
N11 G0 X-10 Y-10
N12 (BSP,X,Y,1)
N13 G1 X0 Y0
N14 G06 X10 Y0
N15 X15 Y5
N16 X15 Y20
N17 G1 G40 X15 Y30
N18 (ESP)
N21 G0 X-10 Y-10
N22 (BSP,X,Y,2)
N23 G1 X0 Y0
N24 G06 X10 Y0
N25 X15 Y5
N26 X15 Y20
N27 G1 G40 X15 Y30
N28 (ESP)
N31 G0 X-10 Y-10
N32 (BSP,X,Y,3)
N33 G1 X0 Y0
N34 G06 X10 Y0
N35 X15 Y5
N36 X15 Y20
N37 G1 G40 X15 Y30
N38 (ESP)
