; Block-only codes (Table 2.2, column "valid only in the block", seed lines 1583-1685): G79, G04,
; G09, G72, G73, G74, G35. Table 2.4 (lines 1917-1986) forbids codes in ONE block only: each of
; these codes may be followed in the next block by a code its row marks 1 (the code is gone by
; then), and `ncc check` (static check and dry run) reports nothing for that; written in one block
; the same pairs are NC3013 (after M30 at the end, where the dry run does not reach them).
; Default machine (power-on G94 G97 G00 G17 G27 G90; probe contacts at the nominal points).
G00 X0 Y0 Z0
; G79 row, column 80: 1.
G79 X10 Y10
G80 X20
TMR=0.5
; G04 row, column 27 28: 1.
G04 X30
G28 X40
; G09 row, column 27 28: 1 (the G27 and G28 rows have 0 in column 09).
G09 X50
G27 X55
G29
; G72 row, column 01: 1 (the G01 row has 0 in column 72 73 74).
G72 X10 E40
G01 X60 F100
; G73 row, column 01: 1.
G73 r5 E41
G01 G91 X1
; G74 row, column 80: 1.
G74 X10 E43
G80 G90 X70
S100 M03
; G35 row, column 00: 1.
G35 G01 X80
G00 X0
M30
; The same pairs in one block: NC3013 at the second code, the note at the first.
G79 G80 X10 Y10
G04 G28 X30
G09 G27 X50
G72 G01 X10 E40
G73 G01 r5 E41
G74 G80 X10 E43
G35 G00 X80
