; source: ../shared/corpus/nc110/part5/5.3.2.3-RED-example.nc (seed section 5.3.2.3)
; expect: origin file with record layout IN, CH, LR, CH, LR; record 1 = origin 0.
; expect: after RED: E10 = field1 (IN), SYVAR0 = field2 (1 char), E41 = field3 (LR), SYVAR2 =
; field4 (1 char), E42 = field5 (LR).
; Changes: the comment after each block is on the line before it (decision 5); the last block,
; added, shows what the RED read. The sandbox holds FILEOR/MP3, record 1: 0, "X", -12.5, "Y", 40.
(DER, 2, E10, SYVAR.CH, E41, SYVAR2.CH, E42)
; открытие файла только для чтения.
(OPN, 1, FILEOR/MP3,R)
; чтение записи 1 (начальная точка 0) из файла, открытого на канале 1.
(RED, 1, 2, 1)
(DIS, E10, " ", SYVAR.CH, " ", E41, " ", SYVAR2.CH, " ", E42)
