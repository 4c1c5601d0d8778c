; Corpus copy of part2/2.8.16-G35-example.nc (seed §2.8.16, L4680-4700, L14716).
; Unchanged except this header and the clock blocks.
; The manual: the motion of N3 starts at the spindle's zero mark (G35 one-shot, written
; in the first block of the group). Derived: N4 "G2 I J" writes no axis: a full circle
; (decision 39) clockwise about X0 Y0 (G90, I0 J0) through X10 Y20, radius 22.3607.
; Expected: N1 G97 G94 spindle_mode/feed_mode events (no change of state), S100, M03;
; N2 rapid to X0 Y0 (the start); N3 path spindle_sync, then the line to X10 Y20;
; N4 arc cw centre X0 Y0 radius 22.3607 sweep 360; N5 rapid to X0 Y0.
; Clock: N3 22.3607 mm at F100 = 13.41641 s; N4 140.4963 mm = 84.29778 s; N5
; max(10,20)/10000 min = 0.12 s: TIM0 97.83419 s (97.83418 as an RE value).
N1 G97 G94 S100 M3
N2 G0 X Y
N3 G1 G35 X10 Y20 F100
N4 G2 I J
N5 G0 X Y
; added: the clock
E25 = TIM0
(DIS,E25)
