; words-implicit-g-unknown: the code an E parameter gives must be a decoded code of
; Table 2.2 (§2.8 seed L1899-1900; decision 15): E1 = 7 gives G07, which is not one:
; NC4049 at run time, at the block (line 8); the rapid of line 6 is made.
E1=7
E2=0
GE2 X5
; error here
GE1 X1
G0 X9
