; corpus-2.13.6.2-dly-example: copy of corpus part4/2.13.6.2-DLY-example.nc
; (§2.13.6.2, seed L9637-9639), unchanged: a dwell of 2 s, E48 = 2, a dwell of
; E48 s. The manual says DLY needs '#' (synchronisation), which its example
; omits; ncc evaluates every block after the motion before it (decision 18).
; Expected: two dwell events of 2 s.
(DLY,2)
E48=2
(DLY,E48)
