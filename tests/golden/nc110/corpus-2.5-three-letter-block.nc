; corpus-2.5-three-letter-block: copy of corpus/nc110/part1/2.5-three-letter-block.nc (§2.5
; seed L1545; §2.13.1.5 L8082 degrees). Expect: a three-letter-code block (EIA 1177 B):
; rotation in the plane by 45 degrees about the active origin (counter-clockwise,
; decision 28): a transform event. Changed: two moves added to show the rotation: X10
; goes to X7.0711 Y7.0711 (10 cos 45, 10 sin 45); X10 Y10 to X0 Y14.1421.
(URT,45)
G0 X10
G0 X10 Y10
