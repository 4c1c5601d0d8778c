; NC-110 §2.8.9.3 1) (seed lines 3997-4060), Table 2.6 ("feed; spindle starts" /
; "reversed" / "feed to R1, rapid to R2"), §2.10.3 (RMS), decision 54: G84 without an
; encoder taps at F; the spindle is reversed at the bottom, the tap comes out at RMS
; percent of F (feed_rate events around the way out) and the spindle turns forward
; again; a stopped spindle is started in its last direction; M4 taps a left-hand thread
; (seed lines 4089-4092).
; Profile cycle-noencoder: the tool starts at X0 Y0 Z100.
; N3: hole X10: XY at 100, rapid to R5, feed F450 to -20, spindle cw (the reverse of
;   M4), feed back to R1 5 at F450 (RMS 100), rapid to R2 12, spindle ccw again (ncc
;   turns the spindle forward after the whole return).
; N5 (RMS=110): hole X20: XY at 12, rapid to 5, feed to -20, spindle cw, feed_rate 495,
;   feed to 5, feed_rate 450, rapid to 12, spindle ccw.
; N6: M5 stops the spindle; no hole. N7: hole X30: XY at 12, rapid to 5, the spindle
;   restarts ccw, then as N5.
; N8: cancel, up to Z50, M5.
N1 S400 F450 T8.8 M6 M4
N2 G84 R5 R12 Z-20
N3 X10
N4 RMS=110
N5 X20
N6 M5
N7 X30
N8 G80 Z50 M5
