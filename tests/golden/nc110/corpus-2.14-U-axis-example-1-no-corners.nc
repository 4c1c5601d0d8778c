; Copy of corpus part4/2.14-U-axis-example-1.nc (NC-110 §2.14, Fig. 2.135, seed lines
; 9968-9990) without the corners N130 r5 and N132 r-3, which ncc cannot run yet (see
; corpus-2.14-U-axis-example-1), so that the rest runs. Corrected: N117 "F60,S630" is
; F60 S630. The annotations after the blocks are dropped.
; Profile frame-uaxis: U diametral, origin 1 = X200 Y100 Z300 U0 (the head's), the tool
; starts at machine Z100; T9.9 has length 150 on Z.
; Checks (decision 32, §2.14): (DPI,Z,U) is allowed under the power-on G27 and makes
; Z-U the plane (N118); (UAO,1) takes every axis of origin 1 (N119); (UOT,0,Z-200)
; puts Z on origin 0 - 200 and leaves X Y U on origin 1 (N120). From there: N121 goes
; to X0 Y160 at the start height (machine Z100 = Z300 from the origin); the first hole
; Z2 U51, chamfer to Z-1 U44.98, bore to Z-44 at F60, back to U40 and Z2; F40 S380;
; the second hole Y0 U106, Z-1 U99.975, Z-15, face to U60, cone to Z-40 U40, Z-44;
; U35, Z100, spindle stop (and coolant off, M05). U is written and shown as a diameter.
; G41/G40 give the cutter_comp events, radius 0 (corrector 9 has radius 0).
; (DPI,X,Y) and (UAO,0) restore the XY plane and origin 0.
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
N131 U60
N133 Z-40 U40
N134 G40 Z-44
N135 G U35
N136 Z100 M5
N137 (DPI,X,Y)
N138 (UAO,0)
