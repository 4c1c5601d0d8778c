; syntax-lowercase: the fourteen lower-case letters of Table 2.1 (seed L1403-1407) are
; addresses distinct from the capitals (decision 2): t (the time of the block) and r in G73
; are read; a c d l m o p s (GTL) and b, u v w, and r outside G73 (cutter radius
; compensation) parse and are reported as not supported yet (NC3034); any other
; lower-case letter is not an address (NC2019).
G1 X1 F100 a30
G1 X1 F100 b5
G21 c1
G1 X1 F100 d5
G21 l1
G1 X1 F100 m5
G21 o1
G21 p1
G1 X1 F100 s1
G1 X1 F100 u1
G1 X1 F100 v1
G1 X1 F100 w-1
G1 X1 F100 r5
G1 X2 F100 t2
G0 X0
G73 r10 E35
e1
f1
