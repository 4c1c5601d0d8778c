; Built from the listing of NC-110 §2.13.1.5, Fig. 2.113 (seed lines 8105-8110 and
; 15609-15615; part4 of the corpus lacks it). The second rendering ends with (URT,0),
; the first with (UAO,0) alone; this copy has both. The three elision lines are replaced
; by a contour: a 40 x 20 rectangle with a G3 R10 corner about (30,10), from Z5.
; Checks (decision 28): everything between (URT,30) and (URT,0) is rotated by +30
; degrees (counter-clockwise) about the temporary origin X100 Y50: the corners
; (40,0) (40,10) (30,20) (0,20) go to X34.641 Y20, X29.641 Y28.6603, X15.9808 Y32.3205,
; X-10 Y17.3205 from the origin (machine X134.641 Y70 ...); the arc's centre (30,10)
; to X20.9808 Y23.6603, still counter-clockwise, radius 10, sweep 90. Z is not rotated.
; (UAO,0) selects origin 0 and (URT,0) cancels the rotation: G0 Y50, the Y the tool is
; at, shows it at machine X100 Y50; G0 X0 Y0 then goes to machine zero.
(UOT,0,X100,Y50)
(URT,30)
G0 X0 Y0 Z5
G1 X40 F100
G1 Y10
G3 X30 Y20 R10
G1 X0
G1 Y0
G0 Z50
(UAO,0)
(URT,0)
G0 Y50
G0 X0 Y0
