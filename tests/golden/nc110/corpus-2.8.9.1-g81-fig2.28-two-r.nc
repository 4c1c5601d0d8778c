; Copy of corpus part2/2.8.9.1-G81-fig2.28-two-R-example.nc (NC-110 §2.8.9.1, Fig. 2.28;
; seed lines 14378-14383, the program exists only in the second rendering).
; Corrected: the depth is printed Z36; with R1 = -10 the hole runs from R1 down, so it
; is Z-36 (/tmp/nc110-corpus.md; the as-printed copy is corpus-2.8.9.1-g81-fig2.28-as-printed).
; Checks: two R words are R1 (approach, -10) and R2 (return, 2) (§2.8.9, decision 52);
; each hole: XY at the tool's height, rapid to R1 -10, feed F100 to -36, rapid to R2 2;
; the first hole's XY move runs at the start height Z100 (profile), the later ones at Z2;
; G80 Z50 cancels, then moves Z in the modal G00; M5 at the end of the block.
N43 S850 F100 T4.4 M6
N44 G81 R-10 R2 Z-36 M3
N45 X35 Y30
N46 X65 Y80
N47 X35 Y120
N48 G80 Z50 M5
