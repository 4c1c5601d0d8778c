; Copy of corpus part2/2.8.9.1-G81-fig2.28-two-R-example.nc as printed (NC-110 §2.8.9.1,
; Fig. 2.28, seed line 14379): the depth Z36 lies above R1 -10, so the G81 block is
; refused (decision 51: "the bottom must lie below R1", NC4068 at the Z word) and the
; holes are not drilled. The corrected copy is corpus-2.8.9.1-g81-fig2.28-two-r.
N43 S850 F100 T4.4 M6
N44 G81 R-10 R2 Z36 M3
N45 X35 Y30
N46 X65 Y80
N47 X35 Y120
N48 G80 Z50 M5
