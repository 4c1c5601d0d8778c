; NC-110 §2.8.9 note 1 (seed lines 3700-3706), decision 51: the block of a canned cycle
; stores it and moves nothing; its one axis word is the depth and its letter is the
; drilling axis; without R both levels are where the tool is.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N2: stores G81 with F150 S900 M8: only the F, S and coolant events, no motion.
; N3: the first hole (10,20): XY at Z100, rapid to R2, feed to Z-12, rapid to R2.
; N5-N7: the depth word X-8 makes X the drilling axis; N6 has no R, so R1 = R2 = X30,
;   where the tool is; N7 positions the hole by Y and Z (rapid to Y40 Z-5 at X30, the
;   tool already at R1), feeds along X to -8 and rapids back to X30.
; N9-N11: the depth word Y-30 with R5 makes Y the drilling axis; N10 (its G00 only sets
;   the modal motion) is the hole at X70 Z-5: rapid there at the tool's Y40, rapid to
;   R Y5, feed to Y-30, rapid to Y5.
N1 S800 F120 M3
N2 G81 R2 Z-12 F150 S900 M8
N3 X10 Y20
N4 G80
N5 G X30
N6 G81 X-8
N7 Y40 Z-5
N8 G80
N9 G81 R5 Y-30
N10 G X70 Z-5
N11 G80
