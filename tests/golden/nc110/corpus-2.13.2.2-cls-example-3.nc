; corpus-2.13.2.2-cls-example-3: copy of corpus part4/2.13.2.2-CLS-example-3-
; main.nc (§2.13.2.2, figure 2.119, seed L8491-8498); the subroutine is
; lib/MP0/S600.nc. S600 is called 3 times, each time on a temporary origin of
; origin 0: (-20,-25), (-15,-50), (60,20) (UOT adds to origin 0, §2.13.1.2).
; Expected (derived): 12 holes, G81 R2 Z-10, at (0,0) (0,-15) (30,-15) (30,0)
; of each temporary origin; in origin-0 coordinates (-20,-25) (-20,-40) (10,-40)
; (10,-25); (-15,-50) (-15,-65) (15,-65) (15,-50); (60,20) (60,5) (90,5) (90,20).
; The trace shows positions from the active origin, and each origin event.
; Changed: the elided N27 Z.. reads Z50 (supplied); N28 M30 added.
; Tools: profiles/flow-tools.toml (T2.2).
N20 S2000 F180 T2.2 M6 M3
N21 (UOT,0,X-20,Y-25)
N22 (CLS,S600)
N23 (UOT,0,X-15,Y-50)
N24 (CLS,S600)
N25 (UOT,0,X60,Y20)
N26 (CLS,S600)
N27 Z50
N28 M30
