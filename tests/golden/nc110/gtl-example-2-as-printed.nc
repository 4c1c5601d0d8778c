; gtl-example-2-as-printed: §2.11.10 example 2 exactly as the manual prints it (corpus
; part3/2.11.10-gtl-example-2.nc). Expect, once each: the typographic quotes of N1
; (NC1001 with the hint), A180 in N5 read as the axis A, named so with the lower-case
; a GTL angle is (NC3045, decision 73), and the ".." the manual writes for values left
; to the reader in N12 (NC1001). N12 refused, no F is in force: NC4001 once, at the
; approach of N15, and the profile makes no more moves (no error follows from it, not
; even l4's, which N5 did not define). gtl-example-2 runs it with the values supplied.
N1 (DIS,”EXAMPLE 2”)
N2 l1=X-50Y10,X30Y50
N3 l2=X30Y50,X70Y10
N4 l3=X70Y0,a-90
N5 l4=X0Y-20,A180
N6 l5=X10Y-20,X0Y0
N7 l6=X0Y0,X-10Y-20
N8 l7=X-50Y0a90
N9 c1=I-10J40r18
N10 c2=I50J30r-14
N11 c3=I40J-20r10
N12 S..M..T3.3M6M..
N13 G0X-30Y0
N14 Z-10
N15 G21 G42 l7
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
N36 G20G40l1
N37 G0Z0
