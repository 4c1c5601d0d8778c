; NC-110 Table 2.6 (G84 and G86: "working feed; the spindle starts"), decision 54 /
; /tmp/nc110-motion.md §5: a stopped spindle is started in the last direction
; programmed; when no direction (M03/M04/M13/M14) was ever programmed, each hole of
; G86 is refused (NC4027 at the hole's block: lines 7 and 8).
N1 S400 F450
N2 G86 R5 Z-20
N3 X10
N4 X20
N5 G80
