; Corpus copy of part2/2.8.1.4-G02-G03-fig2.4-incremental-example.nc (seed §2.8.1.4,
; L2377-2386, Fig. 2.4). Under G91 the end point and the centre are both relative to
; the start (decision 39); G3 and G91 share N20 (Table 2.4 allows it).
; Changed: N50 "G1 Y..." is an elision of the manual and is dropped.
; Expected: the same path as corpus-2.8.1.4-fig2.4-absolute: N20 CCW X-20 Y60 -> X-40 Y80
; about X-40 Y60 (r 20, 90 deg); N30 line to X-45 Y80 (G91 still active); N40 CW to
; X-55 Y90 about X-45 Y90 (r 10, 90 deg); the same clock, 34.61083 s.
N10 G1 X-20 Y60 F200
N20 G3 G91 X-20 Y20 I-20 J0
N30 G1 X-5
N40 G2 X-10 Y10 I0J10
; added: the clock
E25 = TIM0
(DIS,E25)
