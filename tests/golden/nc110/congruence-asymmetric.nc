; Table 2.4: the 28 asymmetric pairs of the printed table (one cell 1, the other 0; listed in
; stdlib/dialects/nc110/congruence.tsv and recomputed here from the seed, lines 1946-1985).
; docs/dialects/nc110.md decision 1: a pair is incompatible if EITHER cell says 1, so each pair is
; an error (NC3013, at the second code, note at the first) in BOTH orders. Each comment line gives
; the two printed cells: row A, column B = a; row B, column A = b.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; G01 (seed line 1947) column G72: 0; G72 (seed line 1969) column G01: 1
G01 G72 X10 E40
G72 G01 X10 E40
; G01 (seed line 1947) column G73: 0; G73 (seed line 1970) column G01: 1
G01 G73 r5 E40
G73 G01 r5 E40
; G01 (seed line 1947) column G74: 0; G74 (seed line 1971) column G01: 1
G01 G74 X10 E40
G74 G01 X10 E40
; G04 (seed line 1950) column G33: 1; G33 (seed line 1961) column G04: 0
G04 G33
G33 G04
; G04 (seed line 1950) column G72: 1; G72 (seed line 1969) column G04: 0
G04 G72 X10 E40
G72 G04 X10 E40
; G04 (seed line 1950) column G73: 1; G73 (seed line 1970) column G04: 0
G04 G73 r5 E40
G73 G04 r5 E40
; G04 (seed line 1950) column G74: 1; G74 (seed line 1971) column G04: 0
G04 G74 X10 E40
G74 G04 X10 E40
; G04 (seed line 1950) column G81: 1; G81 (seed line 1974) column G04: 0
G04 G81
G81 G04
; G04 (seed line 1950) column G82: 1; G82 (seed line 1975) column G04: 0
G04 G82
G82 G04
; G04 (seed line 1950) column G83: 1; G83 (seed line 1976) column G04: 0
G04 G83
G83 G04
; G04 (seed line 1950) column G84: 1; G84 (seed line 1977) column G04: 0
G04 G84
G84 G04
; G04 (seed line 1950) column G85: 1; G85 (seed line 1978) column G04: 0
G04 G85
G85 G04
; G04 (seed line 1950) column G86: 1; G86 (seed line 1979) column G04: 0
G04 G86
G86 G04
; G04 (seed line 1950) column G89: 1; G89 (seed line 1980) column G04: 0
G04 G89
G89 G04
; G09 (seed line 1952) column G27: 1; G27 (seed line 1958) column G09: 0
G09 G27
G27 G09
; G09 (seed line 1952) column G28: 1; G28 (seed line 1959) column G09: 0
G09 G28
G28 G09
; G09 (seed line 1952) column G33: 1; G33 (seed line 1961) column G09: 0
G09 G33
G33 G09
; G09 (seed line 1952) column G72: 1; G72 (seed line 1969) column G09: 0
G09 G72 X10 E40
G72 G09 X10 E40
; G09 (seed line 1952) column G73: 1; G73 (seed line 1970) column G09: 0
G09 G73 r5 E40
G73 G09 r5 E40
; G09 (seed line 1952) column G74: 1; G74 (seed line 1971) column G09: 0
G09 G74 X10 E40
G74 G09 X10 E40
; G09 (seed line 1952) column G81: 1; G81 (seed line 1974) column G09: 0
G09 G81
G81 G09
; G09 (seed line 1952) column G82: 1; G82 (seed line 1975) column G09: 0
G09 G82
G82 G09
; G09 (seed line 1952) column G83: 1; G83 (seed line 1976) column G09: 0
G09 G83
G83 G09
; G09 (seed line 1952) column G84: 1; G84 (seed line 1977) column G09: 0
G09 G84
G84 G09
; G09 (seed line 1952) column G85: 1; G85 (seed line 1978) column G09: 0
G09 G85
G85 G09
; G09 (seed line 1952) column G86: 1; G86 (seed line 1979) column G09: 0
G09 G86
G86 G09
; G09 (seed line 1952) column G89: 1; G89 (seed line 1980) column G09: 0
G09 G89
G89 G09
; G28 (seed line 1959) column G33: 1; G33 (seed line 1961) column G28: 0
G28 G33
G33 G28
