; corpus-2.13.3.2-epp-example-3: copy of corpus part4/2.13.3.2-EPP-example-3.nc
; (§2.13.3.2, figure 2.125, seed L8978-8995): one figure in three orientations.
; Expected (derived): the figure N41-N56 is cut on origin 0 + (50,50) without
; rotation, then by (EPP,1,2) on origin 0 + (-50,0) rotated +30 degrees (N57-
; N59) and on origin 0 + (0,-50) rotated -30 degrees (N60-N62); N63 cancels the
; rotation, N64 restores origin 0. Positions in the trace are from the active
; origin after the rotation (docs/trace.md): the point (50,0) of the figure
; reads (43.3013,25) at +30 degrees and (43.3013,-25) at -30 degrees.
; Corrected: '"Z" N56' reads '"2" N56' (N59 and N62 call (EPP,1,2)).
; Not supported yet: GTL and cutter compensation. Removed: the GTL definitions
; N33-N39 (circles c1 (0,0), c2 (50,0), c3 (25,25), c4 (25,-5); lines l1-l3
; tangent to them; OCR 'z5', 'z8' for r5, r8), G21 G41 (N42), N55 (G20 G40 l1)
; and N45-N49, N51, N53 (Z-1, c4, Z-2, l1 again; the arcs on c2, c3, c1). Supplied
; instead: a G01 triangle through the centres of c1, c2 and c3 at Z-10 (N42
; to c1, N44 along l1 to c2, N50 along l2 to c3, N52 along l3 back to c1).
; Added: N66 M30 for the elided end. Tools: profiles/flow-tools.toml (T1.1).
N32 F200 S1200 T1.1 M6 M3
N40 (UOT,0,X50,Y50)
"1" N41
N42 G1 X Y
N43 Z-10
N44 X50 Y
N50 X25 Y25
N52 X Y
N54 Z2
"2" N56
N57 (UOT,0,X-50,Y)
N58 (URT,30)
N59 (EPP,1,2)
N60 (UOT,0,X,Y-50)
N61 (URT,-30)
N62 (EPP,1,2)
N63 (URT,0)
N64 (UAO,0)
N65 GZ 2
N66 M30
