; corpus-2.4.4-labels: copy of corpus/nc110/part1/2.4.4-labels.nc (§2.4.4 seed L1485-1486).
; Expect: two label-only blocks, START, and END with the block-skip field. Changed: a jump
; to each label is added, with DIS blocks: the jumps skip the "NOT SHOWN" messages and
; the label blocks do nothing: messages 1 and 2 only.
(BNC,START)
(DIS,"NOT SHOWN")
"START"
(DIS,"1")
(BNC,END)
(DIS,"NOT SHOWN")
/"END"
(DIS,"2")
