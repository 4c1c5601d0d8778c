(translate-cycle-moves: ISO's cycles that GOST 20999 and NC-110 drill otherwise, written hole by hole as their moves. G83 pecks Q and comes back at rapid to 0.254 above the depth reached; G99 returns to R, where GOST's cycles return to the level they began at; G85 feeds out to R only, then rapids to the initial level; G84 turns the spindle ccw at the bottom and cw again at R. Expected: over 10,0 at Z20, to R2, pecks to -2 -6 -10, back to Z20; over 20,0 at Z20, to R2, feed to -5, back to R2; over 30,0 at Z20, to R2, feed to -5, feed back to R2, rapid to Z20; over 40,0 at Z20, to R2, feed to -5, M04, feed to R2, M03, rapid to Z20)
G90 G17 G00 X0 Y0 Z20
S1000 M03
G98 G83 X10 Y0 Z-10 R2 Q4 F100
G80
G99 G81 X20 Y0 Z-5 R2
G80 G00 Z20
G98 G85 X30 Y0 Z-5 R2
G84 X40
G80
M30
