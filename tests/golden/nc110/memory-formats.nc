; memory-formats: SA, SK and SYVAR are byte memories read and written in the formats of
; Table 2.7 (§2.10.4-§2.10.5 seed L5028-5200; decision 17): BL a bit (bit 0 the lowest of
; its byte), BY a byte, IN 2 bytes, LI 4, RE 4 (IEEE float), LR 8 (IEEE double), all
; little-endian; the index counts in units of the format (SYVAR2.LR = bytes 16-23,
; L5147-5152); an omitted index is 0 (L5102); the default format is BL for SA and BY for
; SK and SYVAR (L5052-5054, L5092-5094). Everything starts at 0. Overlapping reads show
; the bytes (overlap is the programmer's business, L5133).
(DIS,SYVAR5.LR)
; bytes 0 and 1 read as one IN: 1 + 2*256 = 513
SYVAR0.BY=1
SYVAR1.BY=2
(DIS,SYVAR0.IN)
; IN -2 at bytes 2-3: FE FF
SYVAR1.IN=-2
(DIS,SYVAR2.BY)
(DIS,SYVAR3.BY)
; LI -2147483647 at bytes 4-7: 01 00 00 80
SYVAR1.LI=-2147483647
(DIS,SYVAR4.BY)
(DIS,SYVAR7.BY)
; RE 1.5 at bytes 8-11: 00 00 C0 3F
SYVAR2.RE=1.5
(DIS,SYVAR10.BY)
(DIS,SYVAR11.BY)
; LR -2.25 at bytes 16-23: 00 00 00 00 00 00 02 C0
SYVAR2.LR=-2.25
(DIS,SYVAR22.BY)
(DIS,SYVAR23.BY)
; bits of byte 2 (FE): bit 16 = 0, bit 17 = 1, bit 23 = 1
(DIS,SYVAR16.BL)
(DIS,SYVAR17.BL)
(DIS,SYVAR23.BL)
; no index: SYVAR = SYVAR0 = byte 0 = 1
(DIS,SYVAR)
; SA counts bits: SA12 = bit 4 of byte 1 = 16
SA12=1
(DIS,SA1.BY)
; SK counts bytes
SK5=200
(DIS,SK5.BY)
; reading into E parameters: the values come back
E20=SYVAR1.LI
E30=SYVAR2.LR
E25=SYVAR2.RE
E1=SK5
(DIS,E20)
(DIS,E30)
(DIS,E25)
(DIS,E1)
; a bit written 0 again clears only that bit: byte 2 FE -> FC
SYVAR17.BL=0
(DIS,SYVAR2.BY)
; the last byte of SYVAR (200 bytes) and of SA (bit 8191)
SYVAR199=7
SA8191=1
(DIS,SYVAR199)
(DIS,SA1023.BY)
