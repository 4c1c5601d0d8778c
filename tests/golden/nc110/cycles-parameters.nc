; NC-110 §2.8.9 ("R1, R2 and the depth explicit or as an E parameter", seed lines
; 3541-3553), Table 2.9 (axes, R, I, J, K take LR parameters, E30 up): a cycle written
; with E parameters takes their values when its block runs; changing E31 afterwards
; does not move the stored bottom. The tool starts at 0 0 0.
; G83 R3 Z-20 I8 K.5 J3, hole X10 Y15: XY at Z0, rapid to 3, feed to -5 (peck 8),
; rapid 3, rapid -4, feed -8 (peck 4), rapid 3, rapid -7, feed -10 (2 < J: 3), then
; pecks of 3 from 1 mm above: -12 -14 -16 -18 -20, each followed by a rapid to R1 3.
E30=3
E31=-20
E32=8
E33=0.5
E34=3
E35=10
E36=15
S500 F100 M3
G83 RE30 ZE31 IE32 KE33 JE34
E31=-30
XE35 YE36
G80
