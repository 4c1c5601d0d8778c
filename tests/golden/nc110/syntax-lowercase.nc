; syntax-lowercase: the fourteen lower-case letters of Table 2.1 (seed L1403-1407) are
; addresses distinct from the capitals (decision 2): t (the time of the block) and r in G73
; are read; a d m o belong to GTL definitions (NC3046 in a block that moves); c l p s2,
; r and b are words of a GTL profile's blocks or, r and b, of a compensated path (NC4101
; outside them; s1 is NC3045: only s2 is written); u v w correct the axis the block
; programs (u1 corrects X here; v1 and w-1 NC4101: Y and Z are not programmed); any
; other lower-case letter is not an address (NC2019).
G1 X1 F100 a30
G1 X1 F100 b5
G1 X1 F100 c1
G1 X1 F100 d5
G1 X1 F100 l1
G1 X1 F100 m5
G1 X1 F100 o1
G1 X1 F100 p1
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
