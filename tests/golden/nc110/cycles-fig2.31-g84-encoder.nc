; NC-110 §2.8.9.3 2), Fig. 2.31 with a spindle encoder (seed lines 4115-4126; no corpus
; file): G84 with the pitch K1; "the system computes the feed from S and K" (seed lines
; 4125-4126), so the program has no F at all.
; Corrected: N93 prints "X–51.96" with an en dash for the minus sign; the copy has "-".
; Checks (decision 54): each hole: rapid XY (at Z100, then Z7), rapid to R7, a thread
; move (spindle-synchronised, pitch 1, i.e. 280 mm/min at S280) to Z-15, spindle ccw,
; a thread move back to Z7 (RMS 100 %: no spindle_speed event), spindle cw again;
; holes (-51.96,-30) (51.96,-30) (0,60); no "no feed" error although F was never
; programmed (/tmp/nc110-motion.md §2: "G84 with K and G33 compute their feed").
N91 S280 T8.8 M6 M3
N92 G84 R7 Z-15 K1
N93 X-51.96 Y-30
N94 X51.96
N95 X Y60
N96 G80 Z50 M5
