; ASSET statements as the manual writes them (chapter 5, seed lines in the comments; Cyrillic
; letters of the seed written in Latin) and their other forms: each is read and checked into an
; `asset` statement of the IR (decision 58); asset-run and asset-codes run them.
; seed line 12408: FILQ on MP3, channel 1, read and write
N1 (OPN, 1, FILQ/MP3, W)
; seed line 12486: structure 2 binds E10 (IN), SYVAR bytes 0-9, E40 (LR), SYVAR bytes 10-12, E41
N2 (DER, 2, E10, SYVAR.10CH, E40,SYVAR10.3CH,E41)
; seed line 12497: record 10 into structure 2
N3 (RED, 1, 2, 10)
; seed line 12602
N4 (WRT, 1, 2, 3)
; the record after the last one read or written; a channel, a record given by parameters
N5 (WRT, 1, 2)
N6 (RED, E5, E6, E11)
; seed line 12660: the default device is MP1 (as OPN's)
N7 (CRE, 2, PUNTXZ, 20)
N8 (CRE, E7, X1/MP0, E12)
; seed line 12713
N9 (CAN, PUNTXZ/MP3)
; seed line 12605; every channel of the process
N10 (CLO, 1)
N11 (CLO)
; R is the default; every ASSET format: IN, RE, LR (E parameters or memories) and kCH
N12 (OPN, 2, ORIG)
N13 (OPN, 3, ORIG/MP6, R)
N14 (DER, 1, E19, E25, E30, SA4.IN, SK8.RE, SYVAR20.LR, SK0.CH, SA100.32CH)
N15 M30
