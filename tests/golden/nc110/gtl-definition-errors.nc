; gtl-definition-errors: what a GTL definition may not be (§2.11.2-2.11.7), each an error
; at its word or its definition, once (decision 65): two points without a comma
; between them (§2.11.2); A for the angle a (decision 73); '-' before a point or a
; value; a circle without its radius; a line by a point and a radius (no form of
; §2.11.6); s2 where there is one solution; s3; an index beyond 255; an origin from
; another origin; a point with one coordinate; K in a definition; four operands; o, a,
; d, m in a block that moves (NC3046).
l1 = X1 Y1 X2 Y2
l2 = X1 Y1, A30
p5 = -p1, X3 Y3
l3 = X1 Y1, a-30
l4 = X1 Y1, -a30
c1 = I1 J1
l5 = X0 Y0, r5
l6 = X0 Y0, X5 Y5, s2
p6 = X0 Y0 s3
c256 = I0 J0 r5
o1 = X10 Y10 a30
o2 = o1 X5 Y5 a10
p7 = X10
p8 = X1 K2
c2 = X0 Y0, X1 Y1, X2 Y2, r4
G1 X10 F100 a30
G1 X10 d5
G1 X10 m5 o1
