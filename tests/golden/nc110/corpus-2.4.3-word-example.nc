; corpus-2.4.3-word-example: copy of corpus/nc110/part1/2.4.3-word-example.nc (§2.4.3 seed
; L1437). Expect: linear interpolation to X50.5 Y-3.15 at F200 (mm/min under G94/G71, the
; default power-on state, decision 38); tool 1 corrector 1 selected, the corrector taking
; effect only at M06 (decision 11): a tool_select event, no offset. Changed: nothing.
G1 X50.5 Y-3.15 F200 T1.1
