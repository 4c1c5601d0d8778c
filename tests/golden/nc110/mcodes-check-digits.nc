; An M word has at most two digits: the §1.2.6 format M2 (seed line 371) and §2.7.8 (M followed by
; two digits). M100 and M003 are NC2012 at the word.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
M100
M003
M03 M100
