; Built from the listing of NC-110 §2.13.1.8, example 1, Fig. 2.114 (seed lines
; 8194-8206 and 15649-15661; part4 of the corpus lacks it). The elision line after N212
; is dropped. Corrected: N208 is printed "G Z-100" in both renderings; a retract after
; the cut is meant (the next pass starts with a rapid XY move), so Z100.
; Checks (§2.13.2.1 decision 20: (RPT,2) runs the body twice; decision 27): pass 1:
; X90 Y20, Z2, Z-8 at F150, X40 at F200, G2 to X40 Y60 about (40,40) clockwise,
; radius 20, sweep 180 (through X20 Y40), X90, Z100. N209 (MIR,X) mirrors X; pass 2
; runs mirrored: X-90 Y20, X-40, the arc about X-40 Y40 turns the other way
; (counter-clockwise, through X-20 Y40), X-90. N209 again keeps X mirrored ("set");
; N211 (MIR) cancels it: N212 G Z50 (bare G is G00) leaves the tool at X-90 Y60.
N200 S1500 T8.8 M6 M3
N201 (RPT,2)
N202 G X90 Y20
N203 Z2
N204 G1 Z-8 F150
N205 X40 F200
N206 G2 Y60 I40 J40
N207 G1 X90
N208 G Z100
N209 (MIR,X)
N210 (ERP)
N211 (MIR)
N212 GZ50
