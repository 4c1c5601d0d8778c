; corpus-1.2.18-tmr-dwell: copy of corpus/nc110/part1/1.2.18-tmr-dwell.nc (§1.2.18; Table
; 2.2 note 1; §2.10.1 seed L4935-4966). Expect: dwell time TMR = 2 seconds under G94 (the
; default power-on feed mode, decision 38), used by G04. Changed: a G04 block is added to
; show the dwell of 2 s, and DIS to show the value.
TMR=2
(DIS,TMR)
G4
