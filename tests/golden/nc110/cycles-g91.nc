; NC-110 §2.8.9 under G91 (§2.8.10), decisions 51-52: levels become coordinates where
; they are written, so a cycle defined under G90 keeps absolute R and Z while the holes
; are programmed incrementally (the manual's parametric SUB600/SUB700, §2.13.4, drill
; this way under RPT); under G91, R counts from the axis' position and the depth from R1;
; a zero-length G91 move drills again where the tool is.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N2-N3: G90 definition R3 Z-20; hole (10,10): XY at Z100, rapid 3, feed -20, rapid 3.
; N4-N7: G91, RPT 3 of X15: holes at (25,10) (40,10) (55,10), each at R3 to Z-20.
; N8: cancel, back to G90, up to Z50.
; N9: G91 definition at Z50: R-45 is R1 = R2 = 5, Z-20 the bottom 5-20 = -15.
; N10: X10 Y-10 is the hole at (65,0): XY at 50, rapid to 5, feed to -15, rapid to 5.
; N11: X0 Y0 drills again at (65,0): no XY move, already at R1, feed to -15, rapid to 5.
; N12: R-10 from the tool's Z5: R1 = R2 = -5, nothing moves.
; N13: X5, hole (70,0): XY at 5, rapid to -5, feed to -15 (depth unchanged), rapid -5.
; N14: Z-5 counts from R1 -5: the bottom is -10, nothing moves.
; N15: X5, hole (75,0): XY at -5, feed to -10, rapid to -5. N16: back to G90, Z50.
N1 S800 F100 M3
N2 G90 G81 R3 Z-20
N3 X10 Y10
N4 G91
N5 (RPT,3)
N6 X15
N7 (ERP)
N8 G80 G90 Z50
N9 G91 G81 R-45 Z-20
N10 X10 Y-10
N11 X0 Y0
N12 R-10
N13 X5
N14 Z-5
N15 X5
N16 G80 G90 Z50
