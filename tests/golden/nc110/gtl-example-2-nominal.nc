; gtl-example-2-nominal: gtl-example-2 (§2.11.10 example 2) without G42/G40. The end
; points are the digest's derivation (spec nc110-3 §4.2), checked on the output:
;   N15 corner l7/l1 (-50, 10); N16 l1 -> (-23.638, 23.181); N17 r-8 -> (-16.965,
;   23.402); N18 c1 counter-clockwise 98.660 deg -> (7.457, 35.613); N19 r-8 -> (11.638,
;   40.819); N20 l1 -> (30, 50); N21 l2 -> (40.101, 39.899); N22 c2 clockwise, a half
;   circle -> (59.899, 20.101); N23 l2 -> (70, 10); N24 l3 -> (70, -10); N25 r-10 about
;   (60, -10) -> (60, -20); N26 l4 -> (50, -20); N27 c3 a half circle -> (30, -20); N28
;   l4 -> (14.944, -20); N29 r-8 -> (7.789, -15.578); N30 l5 -> (0, 0); N31 l6 ->
;   (-7.789, -15.578); N32 r-8 -> (-14.944, -20); N33 l4 -> (-40, -20); N34 r-10 about
;   (-40, -10) -> (-50, -10); N35 l7 -> (-50, 10).
N1 (DIS,"EXAMPLE 2")
N2 l1=X-50Y10,X30Y50
N3 l2=X30Y50,X70Y10
N4 l3=X70Y0,a-90
N5 l4=X0Y-20,a180
N6 l5=X10Y-20,X0Y0
N7 l6=X0Y0,X-10Y-20
N8 l7=X-50Y0a90
N9 c1=I-10J40r18
N10 c2=I50J30r-14
N11 c3=I40J-20r10
N12 S1000 F200 M3 T3.3 M6
N13 G0X-30Y0
N14 Z-10
N15 G21 l7
N16 l1
N17 r-8
N18 c1
N19 r-8
N20 l1
N21 l2
N22 c2s2
N23 l2
N24 l3
N25 r-10
N26 l4
N27 c3s2
N28 l4
N29 r-8
N30 l5
N31 l6
N32 r-8
N33 l4
N34 r-10
N35 l7
N36 G20l1
N37 G0Z0
