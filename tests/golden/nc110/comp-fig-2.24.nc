; comp-fig-2.24: the slot of §2.8.7, figure 2.24 (corpus part2/
; 2.8.7-G42-slot-fig2.24-example.nc; its typographic quotes made straight): the contour
; B(50,18) -> 1(15,10) -> 2(7,45) -> 3(77,61) -> 4(85,26) -> B, clockwise, G42 keeps
; the end mill of 12 mm (profile nc110-mills: T9.9 radius 6) inside. B lies on the
; line 4-1, so the tool enters and leaves on it. The digest's derivation, checked on
; the output: N88 ends square to the line B-1 at X48.663 Y23.849 (rule 6); the offset
; corners, where the lines moved 6 inward meet, X19.512 Y17.186, X14.186 Y40.488,
; X72.488 Y53.814, X77.814 Y30.512; N93 (G40) ends at X48.663 Y23.849 again, still
; offset (rule 4); N94 leaves to A (50, 32) as programmed (decision 74).
N84 (DIS,"END MILL MD D=12")
N85 S1100 F170 T9.9 M6
N86 G X50 Y32 M3
N87 Z-305
N88 G1 G42 X50 Y18 F170
N89 X15 Y10
N90 X7 Y45
N91 X77 Y61
N92 X85 Y26
N93 G40 X50 Y18
N94 G X50 Y32
N95 Z M5
