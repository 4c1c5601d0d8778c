; system-value-mcd: MCD lies between 0 and 2 (§2.10.9 seed L5307-5340: MCD = sin(alpha) up
; to 90 degrees, 1 + sin(alpha - 90) up to 180; decision 16): MCD=2.5 is NC4048 at line 4.
MCD=2
MCD=2.5
