(translate-cycle-levels-moves: what NC-110's two-level cycles cannot say of ISO's is written as its moves: a depth alone drills where the tool is in ISO, it sets the depth only in NC-110; under G91 ISO reads R and Z as increments, NC-110 as levels. Expected: over 10,10 at Z50, to R2, feed to -5, back to R2; feed to -8 there, back to R2; 10 further in X at Z2, to R -46, feed to -53, back to -46)
G90 G17 G00 X0 Y0 Z50
G99 G81 X10 Y10 R2 Z-5 F100
Z-8
G80
G91 G99 G81 X10 R-48 Z-7
G90 G80
M30
