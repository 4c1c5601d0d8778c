; corpus-2.4.4-block-skip: copy of corpus/nc110/part1/2.4.4-block-skip.nc (§2.4.4 seed
; L1466-1473; Table 3.3 L11267). Expect: runs only if USB = 1: block 100, a rapid move to
; X100; with USB = 0 the block is a comment. USB starts at 1 (decision 16): the rapid;
; variant .skip (block-skip switch on, USB = 0): no event. Changed: nothing.
/N100G00X100
