; NC-110 §2.8.9.3 2) (seed lines 4104-4126), §2.10.3 (RMS), decision 54: with a spindle
; encoder and K, G84 taps spindle-synchronised at the pitch K (feed = K x rpm, whatever
; F says), reverses the spindle at the bottom, comes out at RMS percent of the spindle
; speed (spindle_speed events around the way out) and turns forward again.
; Profile cycle-mill (encoder): the tool starts at X0 Y0 Z100; rapids 10000 mm/min.
; N1 programs an F the K form must not use. TIM0 is of class RE (single precision), so
; the times show as 8.160857201 and 8.545714378.
; N5: hole (10,10): rapid XY (0.06 s), rapid Z100 -> 7 (93 mm, 0.558 s), thread to
;   Z-15 at 1.25 x 280 = 350 mm/min (22 mm, 3.771429 s), spindle ccw, thread back to
;   Z7 (3.771429 s), spindle cw: E31 = 8.160857 s.
; N9 (RMS=80): hole (20,10): rapid X (0.06 s), thread in (3.771429 s), spindle ccw,
;   spindle_speed 224 (80 % of 280), thread out at 1.25 x 224 = 280 mm/min
;   (4.714286 s), spindle_speed 280, spindle cw: E32 = 8.545714 s.
N1 F500
N2 S280 T8.8 M6 M3
N3 G84 R7 Z-15 K1.25
N4 E30=TIM0
N5 X10 Y10
N6 E31=TIM0-E30
N7 RMS=80
N8 E30=TIM0
N9 X20
N10 E32=TIM0-E30
N11 (DIS,E31," ",E32)
N12 G80 Z50 M5
