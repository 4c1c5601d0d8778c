; Copy of corpus part4/2.14-U-axis-example-1.nc (NC-110 §2.14, Fig. 2.135, seed lines
; 9968-9990): a boring and facing head with a diametral U axis finishes two holes. The
; annotations after the blocks are dropped. Corrected: N117 is printed "F60,S630" (both
; renderings); here F60 S630 (the printed form is corpus-2.14-U-axis-example-1-as-printed).
; Profile frame-uaxis: U diametral, origin 1 the head's, tools T9.9 and T10.
; Checks: the corners r5 (N130) and r-3 (N132) need the cutter radius compensation's
; geometry, which ncc does not have yet: NC3034 at their r words; every other block,
; (DPI,Z,U) under the power-on G27 included (decision 32), has no error. The run of the
; program without those two blocks is corpus-2.14-U-axis-example-1-no-corners.
N116 (DIS,".....................")
N117 F60 S630 T9.9 M6
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
