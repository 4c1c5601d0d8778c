; corpus-2.5-assignment-blocks-gtl: corpus/nc110/part1/2.5-assignment-blocks.nc as the
; corpus has it (§2.5 seed L1534-1536, Cyrillic Е30 and р2 made Latin). Expect: the GTL
; point p2 = X10 Y25 (§2.11.5) is stored, as the E parameter and UOV are: no error, and
; nothing moves.
E30 = 28.5
p2 = X10 Y25
UOV=1.5
