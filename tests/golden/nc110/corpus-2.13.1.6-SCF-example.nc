; Built from the listing of NC-110 §2.13.1.6 (seed lines 8136-8142 and 15627-15631; part4
; of the corpus lacks it). The manual's annotations after " - " are dropped; the
; elision lines are replaced by moves.
; Checks (§2.13.1.6, decision 28): (SCF,3) scales every configured axis by 3:
; G0 X10 Y10 Z10 goes to X30 Y30 Z30; G1 X20 to X60 Y30; the arc G2 X30 Y20 about
; (20,20), radius 10, to X90 Y60 about X60 Y60, radius 30, still clockwise, sweep 270.
; F is not scaled (feed_rate 100). (SCF,2,X) scales X by 2 and cancels the factor 3
; on the other axes (L8138): X20 Y10 Z10. (SCF) cancels every factor: X10 Y10 Z10.
; The JSON Lines trace records the factor of every axis: (SCF,3) is 3 on the linear
; axes X Y Z U V W and 1 on the rotary A B C; (SCF,2,X) is 2 on X and 1 on the others.
G0 X10 Y10 Z10
(SCF,3)
G0 X10 Y10 Z10
G1 X20 F100
G2 X30 Y20 I20 J20
G0 X10 Y10 Z10
(SCF,2,X)
G0 X10 Y10 Z10
(SCF)
G0 X10 Y10 Z10
