; memory-overflow: a value outside the format is a run-time error, not a wrap
; (decision 17 with decision 8; NC4032): E30 = 256 does not fit SYVAR1.BY (line 7).
E30=255
SYVAR1.BY=E30
(DIS,SYVAR1.BY)
E30=256
SYVAR1.BY=E30
