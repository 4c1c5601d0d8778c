; At most four M words in a block (NC3014): §2.7.8 (seed lines 1889-1890: "up to four M functions
; in each block") and §2.8.1.1 (lines 2056-2058: "up to 4 M, 1 S and 1 T"). The error stands at
; the fifth M word; a sixth is not reported again. The codes here share no conflict set (NC3005).
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; Four M words: allowed.
M03 M08 M10 M41
; Four M words with other words between them and one-digit forms: allowed.
N10 M3 X10 M8 S100 M10 T1.1 M41
; Five: NC3014 at the fifth (M60, column 17).
M03 M08 M10 M41 M60
; Six: one error, at the fifth (M6, column 15); the sixth (M60) is not counted again.
M3 M8 M10 M41 M6 M60
; Five with the fifth after axis words: NC3014 at M06 (column 25).
M03 M07 X10 M10 M41 Y10 M06
