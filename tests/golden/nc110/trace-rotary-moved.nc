; trace-rotary-moved: the text trace shows an axis beyond X Y Z once it has been away
; from zero or has moved (decision 77): with profile motion-endless, B is an endless
; rotary axis shown 0..359.9999; a G91 turn of 360 deg from B0 ends at B0 and shows
; "B0" (before, a move that ended where B showed 0 printed no B). A move that leaves B
; alone after it shows it still.
N1 G X10 Y0
N2 G91 G1 B360 F3600
N3 G90 X20
