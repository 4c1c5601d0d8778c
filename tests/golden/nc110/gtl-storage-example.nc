; gtl-storage-example: the storage example of §2.11.2 (corpus part3/
; 2.11.2-storage-example.nc, the Cyrillic о of its first line made Latin). Its
; definitions are valid syntax, but p3 = l3, c1 has no solution: l3 (from the zero to
; (100, 60)) passes 45.30 from c1's centre (29.046, 70.259), more than its radius 15
; (spec nc110-3 §4.6). Expect NC4100 at p3, naming l3 and c1; the run stops there.
; (ncc check goes on: c2 = p3, r8 fails with p3, without a second message.)
o1 = X30 Y30 a45
p1 = o1 X15 Y15
p2 = X60 Y30
l1 = p1, p2
l2 = X30 Y50, a45
c1 = l1, l2, r15
l3 = X0 Y0, X100 Y60
p3 = l3, c1
c2 = p3, r8
