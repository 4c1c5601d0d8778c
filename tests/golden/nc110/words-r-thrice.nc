; words-r-thrice: R may stand twice, R1 and R2, only in a canned-cycle block (§2.8.9 seed
; L3544-3549; addresses.tsv repeat "twice"); a third R is an error: NC3001 "R appears more than
; twice in the block" at the third R (line 5 column 11), with a note at the first (R1, column
; 5). The run stops before any motion.
G81 R1 R2 R3 Z-5 F100
