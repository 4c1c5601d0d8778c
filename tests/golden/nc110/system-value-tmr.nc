; system-value-tmr: TMR, the dwell time, is not negative (§2.10.1 seed L4935-4966;
; decision 16): TMR = E30 with E30 = -1 is NC4048 at line 5 when the run gets there.
TMR=0
E30=-1
TMR=E30
