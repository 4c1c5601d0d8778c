; The machine profile's [asset] limits (docs/profile.md): 2 channels, 2 structures, 200 bytes a
; device (asset-profile.toml). ERR=1: each code goes to IOSTA. A structure beyond the machine's is
; not an I/O error (DER has no code, §5.4): the run stops there (NC4086).
ERR=1
(DER, 1, SYVAR.32CH)
(OPN, 1, A)
(OPN, 2, A)
(OPN, 3, A)
(DIS, "CHANNEL 3: ", IOSTA)
(CRE, 1, B, 1)
(DIS, "NO CHANNEL LEFT: ", IOSTA)
(CLO)
(CRE, 1, B, 5)
(DIS, "5 RECORDS OF 32: ", IOSTA)
(CRE, 1, C, 4)
(DIS, "4 RECORDS OF 32: ", IOSTA)
(DER, 3, E10)
(DIS, "NOT REACHED")
M30
