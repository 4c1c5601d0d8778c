; corpus-2.13.4-cls-circular-grid: copy of corpus part4/2.13.4-CLS-circular-
; grid-main.nc (§2.13.4, figure 2.126, seed L9042-9055); the subroutine is
; lib/MP0/SUB800.nc. Parameters (legend L9012-9020): E1 holes = 6, E2 cycle =
; 81, E30/E31 centre (50,50), E32 radius 30, E33 start angle 45, E34 step 45,
; E36 R = 2, E37 Z = -10.
; Expected (derived): 6 G81 holes at 45, 90, ..., 270 degrees on radius 30 about
; (50,50), in origin-0 coordinates (71.213,71.213) (50,80) (28.787,71.213)
; (20,50) (28.787,28.787) (50,20); the trace shows them from the temporary
; origin (50,50), rotated: (21.2132,21.2132) (0,30) (-21.2132,21.2132) (-30,0)
; (-21.2132,-21.2132) (0,-30). At the end E25 = 315, origin 0, no rotation.
; Added: N56 (DIS,E25) and N57 M30 (the manual elides the end).
; Tools: profiles/flow-tools.toml (T2.2).
N43 (DIS,"...............")
N44 S900 F70 T2.2 M6 M3
N45 E30=50
N46 E31=50
N47 E32=30
N48 E33=45
N49 E34=45
N50 E1=6
N51 E36=2
N52 E37=-10
N53 E2=81
N54 (CLS,SUB800)
N55 G Z20 M5
N56 (DIS,E25)
N57 M30
