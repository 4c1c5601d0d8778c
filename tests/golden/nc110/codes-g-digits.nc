; A G word has at most two digits: §2.8 (seed lines 1896-1897, "the symbol G followed by two digits
; (max.)") and the §1.2.6 format G2 (line 371). G100 and G001 are NC2012 at the word, whatever the
; number; G1 and G01 are the same code (see congruence-forms).
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
G100 X1
G001 X1
G01 G100 X1
N5 G123
