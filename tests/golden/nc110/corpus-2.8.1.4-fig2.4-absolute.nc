; Corpus copy of part2/2.8.1.4-G02-G03-fig2.4-absolute-example.nc (seed §2.8.1.4,
; L2330-2386, Fig. 2.4, labels r20 r10 at L13934-13935). G90 (power-on): I J are the
; absolute centre (decision 39).
; Changed: N50 "G1 Y..." is an elision of the manual and is dropped.
; Expected (the manual): N20 counter-clockwise from X-20 Y60 to X-40 Y80 about X-40 Y60;
; N30 line to X-45 Y80; N40 clockwise from X-45 Y80 to X-55 Y90 about X-45 Y90.
; Derived: N20 radius 20, 90 degrees; N40 radius 10, 90 degrees.
; Clock: N10 63.2456 mm, N20 31.4159, N30 5, N40 15.7080 at F200 = 34.61083 s.
N10 G1 X-20 Y60 F200
N20 G3 X-40 Y80 I-40 J60
N30 G1 X-45
N40 G2 X-55 Y90 I-45J90
; added: the clock
E25 = TIM0
(DIS,E25)
