; gtl-example-3-as-printed: §2.11.10 example 3 exactly as the manual prints it (corpus
; part3/2.11.10-gtl-example-3.nc). Expect, once each: N1's text without quotes
; (NC3018), and the ".." the manual writes for values left to the reader in N2 and N41
; (NC1001). N2 refused, no F is in force: NC4001 once, at the approach of N20.
; gtl-example-3 runs it with them supplied.
N1 (DIS,EXAMPLE 3)
N2 S..F..T1.1M6M..
N3 o1=X20Y21a45
N4 l1=X0Y-60a180
N5 l2=X50Y0,a90
N6 c6=o1I-38J-35r10
N7 l3=c6,a135
N8 l4=c6,a-45
N9 l5=X0Y-50,a180
N10 l6=X-50Y-65,a60
N11 l7=X-25Y0,a90
N12 c3=I-65J0r55
N13 c4=I0J80r55
N14 p2=c3,c4
N15 c1=p2,r-15
N16 p3=X40Y80
N17 c2=c1,p3,r40
N18 c5=I55J80r13
N19 l8=X70Y0,a-90
N20 G21 G42 l8
N21 Z-10
N22 l1
N23 r-5
N24 l2
N25 r12
N26 l3
N27 c6
N28 l4
N29 l5
N30 l6
N31 l7
N32 r40
N33 c1
N34 c2
N35 r-5
N36 c5
N37 r-5
N38 l8
N39 G20 G40 l1
N40 G Z
N41 X..Y..M30
