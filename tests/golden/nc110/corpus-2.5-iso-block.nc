; corpus-2.5-iso-block: copy of corpus/nc110/part1/2.5-iso-block.nc (§2.5 seed L1524).
; Expect: linear interpolation to X500 Y20 at feed F200 (mm/min, G94 at power-on,
; decision 38). Changed: nothing.
G1 X500 Y20 F200
