; Copy of corpus part2/2.8.9.2-G83-fig2.29-example.nc (NC-110 §2.8.9.2, Fig. 2.29, seed
; lines 3907-3925): deep drilling with chip unloading at three points.
; Corrected: N67 prints "R.8", a second R (R2 = 0.8) where the factor K.8 is meant
; (compare Fig. 2.30, seed line 3971); the copy has K.8. The as-printed copy is
; corpus-2.8.9.2-g83-fig2.29-as-printed. The Russian annotations after the blocks are
; moved into these comments: N67 "cycle definition", N68-N70 "drilling at point 1, 2,
; 3", N71 "tool lift and cycle cancel" (the prose says N17 where N71 is meant).
; Checks (decision 53, /tmp/nc110-motion.md §5.1): I20 K.8 J6 with R1 3 and Z-55,
; 5 pecks per hole: feed to -17, -32, -43.8, -53.04, -55; after each peck a rapid back
; to R1 3 (chip unloading) and a rapid down to 1 mm above the depth reached (-16,
; -31, -42.8, -52.04); the peck shrinks 20, 16, 12.8, 10.24, 8.192 (all >= J6);
; the return is a rapid to R1 3 (no R2); holes 2 and 3 move in XY at Z3.
N66 S930 F65 T6.6 M6
N67 G83 R3 Z-55 I20 K.8 J6 M13
N68 X-15.81 Y-22.2
N69 X23
N70 X9 Y35.8
N71 G80 Z50 M5
