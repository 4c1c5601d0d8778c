; source: ../shared/corpus/nc110/part5/5.3.2.6-CRE-example.nc (seed section 5.3.2.6)
; expect: structure 2 = SYVAR0 (1 CH), E40 (LR), SYVAR1 (1 CH), E41 (LR); file PUNTXZ created on
; the default device with 20 records of that layout.
; expect: after the loop: records 1..20 each contain "X", measured X (E40), "Z", measured Z (E41)
; of the 20 measured points, written sequentially (WRT without record number) starting at record
; 1; channel 1 closed.
; Changes: the comments after the blocks are left out (decision 5) and the ';' after (RPT,20);
; "Х" is Latin X (the seed's is Cyrillic, two bytes: it does not fit SYVAR.CH); the measuring
; block "G72X размер Z размер Е40" (placeholders for the nominal point) becomes two assignments
; that step E40 and E41 as 20 measurements would, so the file's contents are known: record k holds
; X = 1.5k and Z = -0.25k. "SYVAR 1. CH" is kept as printed (the blanks are allowed: SYVAR1.CH).
; The default device of CRE and OPN is MP1 (decision 58).
(DER, 2, SYVAR.CH, E40, SYVAR 1. CH, E41)
(CRE, 2, PUNTXZ, 20)
(OPN, 1, PUNTXZ, W)
SYVAR.CH = "X"
SYVAR1.CH="Z"
(RPT,20)
E40=E40+1.5
E41=E41-0.25
(WRT, 1, 2)
(ERP)
(CLO, 1)
