(translate-cycle-levels: ISO's one-level canned cycles into NC-110's two levels. G99 returns to R, NC-110's one R; G98 to where the cycle began, NC-110's second R. ISO's cycle block drills at its position, NC-110's stores the cycle and its next block drills. P is TMR's time. A later block's depth or return level are NC-110's levels again. G00 ends ISO's cycle, NC-110's needs G80 first. Expected: over 10,10 at Z50, to R2, feed to Z-5, back to Z2; 20,10 to Z-8, back to Z2; 30,10 to Z-8, back to Z50; G82 at 40,10 and 50,10 from R3 to Z-4 with 1.5 s at the bottom, back to R3; then a rapid to 0,0,50)
G90 G17 G00 X0 Y0 Z50
G99 G81 X10 Y10 R2 Z-5 F100
X20 Z-8
G98 X30
G80
G99 G82 X40 Y10 R3 Z-4 P1500
X50
G00 X0 Y0 Z50
M30
