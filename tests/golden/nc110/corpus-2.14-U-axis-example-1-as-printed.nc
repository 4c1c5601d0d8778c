; Copy of corpus part4/2.14-U-axis-example-1.nc (NC-110 §2.14, seed lines 9968-9990) with
; N117 as printed: "F60,S630" has a comma between the words (both renderings). The
; annotations after the blocks are dropped.
; Checks: the comma is an error at line 8, column 9, and the block is not read, so the
; dry run finds no feed rate for the G1 moves N123 and N124 (NC4001, said once, at
; N123); the corners r5
; and r-3 are cut as in corpus-2.14-U-axis-example-1.
N116 (DIS,".....................")
N117 F60,S630 T9.9 M6
N118 (DPI,Z,U)
N119 (UAO,1)
N120 (UOT,0,Z-200)
N121 X Y160 T10 M3
N122 G41 Z2 U51
N123 G1 Z-1 U44.98
N124 Z-44
N125 G G40 U40
N126 Z2 F40 S380
N127 G41 Y U106
N128 G1 Z-1 U99.975
N129 Z-15
N130 r5
N131 U60
N132 r-3
N133 Z-40 U40
N134 G40 Z-44
N135 G U35
N136 Z100 M5
N137 (DPI,X,Y)
N138 (UAO,0)
