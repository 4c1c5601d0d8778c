; corpus-2.10.5-syvar-addressing-examples: from corpus/nc110/part3/
; 2.10.5-syvar-addressing-examples.nc (§2.10.5 seed L5140-5152), an addressing
; illustration, not a program. Expect: SYVAR0.BY = byte 0, SYVAR1.CH = byte 1, SYVAR1.IN
; = bytes 2-3, SYVAR1.LI = bytes 4-7, SYVAR2.RE = bytes 8-11, SYVAR2.LR = bytes 16-23: no
; overlaps; SYVAR 1.4CH addresses four characters from byte 1. Corrected: OCR SYVARO =
; SYVAR0, SIVAR = SYVAR; the list numbers, the Russian text and the elision are dropped.
; Made a program: a value is written through each reference and read back unchanged;
; then SYVAR 1.4CH = "WXYZ" overwrites bytes 1-4, which shows in the overlapping
; references: SYVAR1.IN = 88 + 89*256 = 22872; SYVAR1.LI = 0x0001865A = 99930.
SYVAR0.BY=200
SYVAR1.CH="Q"
SYVAR1.IN=-300
SYVAR1.LI=100000
SYVAR2.RE=2.5
SYVAR2.LR=-1.125
(DIS,SYVAR0.BY)
(DIS,SYVAR1.CH)
(DIS,SYVAR1.IN)
(DIS,SYVAR1.LI)
(DIS,SYVAR2.RE)
(DIS,SYVAR2.LR)
; bytes 12-15, between the RE and the LR, are untouched
(DIS,SYVAR3.LI)
SYVAR 1.4CH="WXYZ"
(DIS,SYVAR0.BY)
(DIS,SYVAR1.CH)
(DIS,SYVAR1.IN)
(DIS,SYVAR1.LI)
