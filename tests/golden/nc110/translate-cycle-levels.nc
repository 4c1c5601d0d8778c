; translate-cycle-levels: NC-110's two-level canned cycles into the one-level dialects.
; The cycle's block stores it; the first hole is the target's cycle block. R2 is where
; the tool stands when the first hole begins (ISO's G98) or R1 (G99); TMR is the
; dwell's time (ISO's P). A block with levels alone sets them, the next hole writes
; them. Expected: over 10,10 at Z10, to R2, feed to Z-5, back to Z10; over 20,10 the
; same; then depth Z-8 at 30,10, back to Z10; G82 over 40,10 from R3 to Z-4, 2 s at
; the bottom, back to R3; then a rapid to 0,0,10
G00 X0 Y0 Z10
G81 R2 R10 Z-5 F100
X10 Y10
X20
Z-8
X30
G80
TMR=2
G82 R3 Z-4
X40
G80
G00 X0 Y0 Z10
M30
