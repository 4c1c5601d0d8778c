; gtl-profile-errors: what a GTL profile may not be (§2.8.6, §2.11.8, §2.11.9), each
; reported once at its block by ncc check, which goes on after each profile: a fillet
; right after G21; elements that neither meet nor have a fillet between them; a
; chamfer beside a circle; a start point off the first element; a point inside the
; profile; an axis of the profile's plane; G21 under G91; two elements in one block; a
; fillet in an element's block; an element undefined; l outside a profile; G20 without
; G21; a program that ends inside a profile. After the first error of a profile its
; other blocks are read, not run, up to its G20 (decision 68).
l1 = X0 Y0, a0
l2 = X0 Y10, a0
l3 = X20 Y0, a90
c1 = I10 J5 r3
p1 = X0 Y0
p2 = X0 Y1
F100
G21 p1
r2
l1
G20 l1
G21 p1
l1
l2
G20 p1
G21 p1
l1
b2
c1
G20 p1
G21 p2
l1
G20 p1
G21 p1
l1
p2
G20 p1
G21 p1
l1 X5
G20 p1
G91 G21 p1
G90 G20 p1
G21 p1
l1 c1
G20 p1
G21 p1
l1 r2
G20 p1
G21 p1
l9
G20 p1
G1 X1 l1
G20 p1
G21 p1
l1
