; NC-110 §2.8.9.4 2), Fig. 2.33 (second rendering, seed lines 14512-14520; N45-N46 are
; lost in the first rendering; no corpus file): a block X Y R1 R2 sets both levels and
; the hole returns to the new R2; a later single R sets R1 = R2 (decision 52).
; The point numbers printed before N45-N49 are left out. The prose (seed line 4250)
; says "R=3" for N48-N49 where the block has R-3; the block is kept.
; Checks:
;   N45 (25,25): XY at Z100, rapid to -18, feed to -46, rapid to -18 (R1 = R2 = -18);
;   N46 X60 R-18 R-8: XY at -18, already at R1, feed to -46, rapid to the new R2 -8;
;   N47 Y75 R-8 R2 Z-25: XY at -8, already at R1 -8, feed to the new depth -25,
;       rapid to R2 +2;
;   N48 Y175 R-3 Z-46: XY at +2, rapid down to -3, feed to -46, rapid to -3;
;   N49 X95: XY at -3, feed to -46, rapid to -3; N50 cancels, up to Z50.
N42 (DIS,"...............")
N43 S1000 F100 T5.5 M6
N44 G81 R-18 Z-46 M13
N45 X25 Y25
N46 X60 R-18 R-8
N47 Y75 R-8 R2 Z-25
N48 Y175 R-3 Z-46
N49 X95
N50 G80 Z50 M5
