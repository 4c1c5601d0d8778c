; Copy of corpus part2/2.8.9.2-G83-fig2.29-example.nc as printed (NC-110 §2.8.9.2,
; Fig. 2.29, seed line 3909): "R.8" is a second R word, so it reads as R2 = 0.8 below
; R1 = 3 (and no K): the return level on the depth side of R1 is refused (NC4068) at
; that second R word, 7:21, saying that R2 must not lie below R1.
; The corrected copy (K.8) is corpus-2.8.9.2-g83-fig2.29. Annotations removed.
N66 S930 F65 T6.6 M6
N67 G83 R3 Z-55 I20 R.8 J6 M13
N68 X-15.81 Y-22.2
N69 X23
N70 X9 Y35.8
N71 G80 Z50 M5
