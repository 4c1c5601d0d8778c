; system-value-erf: ERF, the form tolerance of the G27 corners, is not negative (§2.10.8;
; decision 16): ERF=-1 is NC4048 at line 4.
ERF=0
ERF=-1
