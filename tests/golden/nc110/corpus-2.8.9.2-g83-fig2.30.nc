; Copy of corpus part2/2.8.9.2-G83-fig2.30-example.nc (NC-110 §2.8.9.2, Fig. 2.30, seed
; lines 3967-3974): deep drilling with chip unloading, one hole at X0 Y0.
; Corrected: N61 prints (DIS,"TWIST DRILL D=6) with a typographic opening quote and no
; closing quote; the copy has plain quotes on both sides (the as-printed copy is
; corpus-2.8.9.2-g83-fig2.30-as-printed). No F is programmed anywhere in the excerpt,
; so F50 is added to N63. N66 "G.. X.. Z.." is an elision; the copy supplies G0 X100 Z50.
; Checks (decision 53, /tmp/nc110-motion.md §5.1): R5 Z-120 I20 K.8 J6, 18 pecks:
; bottoms -15 -30 -41.8 -51.04 -58.232 -63.7856 (pecks 20 16 12.8 10.24 8.192 6.5536),
; then the peck 5.24288 is below J6 so it is 6 from 1 mm above the depth reached:
; -68.7856 -73.7856 ... -118.7856, and the last clipped at -120; each peck but the last
; is followed by a rapid to R1 5 and a rapid to 1 mm above the depth reached; the tool
; already stands over X0 Y0, so the hole starts with the rapid to R1; exit to Z5.
N61 (DIS,"TWIST DRILL D=6")
N62 G97 S1000 T3.3 M6 M3 M7
N63 G83R5 Z-120 I20 K.8 J6 F50
N64 X0 Y0
N65 G80
N66 G0 X100 Z50
