; corpus-2.5-assignment-blocks-gtl: corpus/nc110/part1/2.5-assignment-blocks.nc as the
; corpus has it (§2.5 seed L1534-1536, Cyrillic Е30 and р2 made Latin). Expect: the GTL
; point p2 = X10 Y25 (§2.11) parses and is reported as not supported yet (NC3034, at
; line 6, docs/dialects/nc110.md); the other two blocks are fine.
E30 = 28.5
p2 = X10 Y25
UOV=1.5
