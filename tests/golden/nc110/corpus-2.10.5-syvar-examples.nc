; corpus-2.10.5-syvar-examples: copy of corpus/nc110/part3/2.10.5-syvar-examples.nc
; (§2.10.5 seed L5096-5107). Expect: SYVAR written from an E parameter, an expression, a
; constant and a text, and read into E parameters; the default format is BY; SYVAR =
; SYVAR0.BY = byte 0, SYVAR1.IN = bytes 2-3, SYVAR2.LR = bytes 16-23, SYVAR16.3CH = bytes
; 16-18, over SYVAR2.LR (the manual warns of overlaps). Added: E3 = 5 and E4 = 7 first
; (supplied values), DIS blocks, and a second read of SYVAR2.LR after the text: the bytes
; 41 42 43 0 0 0 0 0 read as a double are 2.177778621e-317.
E3=5
E4=7
SYVAR = E4
SYVAR1 = E3+E4
SYVAR1.IN = 268
E4 = SYVAR
E35 = SYVAR2.LR
SYVAR16.3CH = "ABC"
E36 = SYVAR2.LR
; 7, 12, 268 (= 12 + 256), 7, 0, ABC, the denormal
(DIS,SYVAR)
(DIS,SYVAR1)
(DIS,SYVAR1.IN)
(DIS,E4)
(DIS,E35)
(DIS,SYVAR16.3CH)
(DIS,E36)
