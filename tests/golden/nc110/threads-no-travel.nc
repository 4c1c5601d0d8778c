; A G33 block whose axis words do not move (§2.8.1.7; decision 42: the pitch is measured
; along the longest travel), ncc check. G29: no G27 profile rule.
; Expected: one error at 7:1, NC4076 (a thread code of its own, citing §2.8.1.7): "G33
; needs a move to cut the thread along: no axis of the block travels" (not NC4066, the
; arc-form code of §2.8.1.4).
N0 G29 G0 Z0 S100 M3
N1 G33 Z0 K2
