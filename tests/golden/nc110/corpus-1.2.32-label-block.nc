; corpus-1.2.32-label-block: copy of corpus/nc110/part1/1.2.32-label-block.nc (§1.2.32 seed
; L834). Expect: one block with the block-skip field '/', the label НАЧАЛО (6 Cyrillic
; characters) and block number 125, no instruction; it runs only if USB = 1 (and does
; nothing). Changed: a jump to the label before it and DIS blocks around it are added: the
; jump skips "NOT SHOWN", the label block does nothing, "AFTER" shows (also with USB = 0,
; variant .skip).
(BNC,НАЧАЛО)
(DIS,"NOT SHOWN")
/"НАЧАЛО"N125
(DIS,"AFTER")
