; NC-110 §2.8.9 (G80, Table 2.6), decision 52: "G80's axis words move in the modal
; motion"; a G00/G01 in a hole block only sets the modal motion (Table 2.4 lets G8x
; share a block with G00/G01); the cycle's own positioning is always a rapid.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N2: G01 at F200 to (5,5,100).
; N4: a hole at (10,5) while G01 is modal: rapid XY, rapid to R2, feed to -10, rapid 2.
; N5: G80 cancels, then Z50 moves as a feed (modal G01).
; N7: G0 in a hole block: the hole at (20,5): XY at Z50, rapid to 2, feed, rapid to 2.
; N8: G80 with Y and Z: a rapid (modal G00 since N7) to (20,20,60).
; N9: no cycle any more: X30 is a plain rapid.
N1 S800 F200 M3
N2 G1 X5 Y5
N3 G81 R2 Z-10
N4 X10
N5 G80 Z50
N6 G81 R2 Z-10
N7 G0 X20
N8 G80 Y20 Z60
N9 X30
