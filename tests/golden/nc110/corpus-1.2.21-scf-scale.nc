; Copy of corpus part1/1.2.21-scf-scale.nc (NC-110 §1.2.21, seed lines 627-628; the
; rule is §2.13.1.6, lines 8112-8142). The manual's prose after each block ("для всех
; осей", "для оси X") is dropped. Added: the same move after each SCF block, so the
; trace shows the scale, and a last (SCF) that cancels it.
; Checks: (SCF,2) scales every linear axis by 2 (decision 28: not the angles of A B C):
; X10 Y10 Z5 goes to X20 Y20 Z10; (SCF,2,X) scales X by 2 and cancels the scale on the
; others (L8127): X20 Y10 Z5; (SCF) cancels all: X10 Y10 Z5.
(SCF,2)
G0 X10 Y10 Z5
(SCF,2,X)
G0 X10 Y10 Z5
(SCF)
G0 X10 Y10 Z5
