; source: ../shared/corpus/nc110/part5/5.3.2.2-DER-example.nc (seed section 5.3.2.2), as printed
; expect: file FILE/MP3 has record layout IN, CH(10), LR, CH(3), LR.
; expect: structure 2 = field1 -> E10 (IN), field2 -> SYVAR bytes 0..9 (10 CH), field3 -> E40 (LR),
; field4 -> SYVAR bytes 10..12 (3 CH), field5 -> E41 (LR).
; expect: literal result: the file is opened on channel 3 but RED names channel 1: an ASSET error
; "channel not open" (code 1 or 8, see spec). ncc: code 8, "file not open" (docs/asset.md,
; Statements); ERR is 0 at power-on, so the run stops there, at the RED.
; Changes: the comment after each block is on the lines before it (decision 5: ';' starts a
; comment block only; a block holds at most 128 characters).
; открывается файл для записи на канале 3
(OPN, 3, FILE/MP3,W)
; определение для структуры двух следующих переменных: - поле 1 - Е10 - поле 2 - SYVAR
; - поле 3 - E40 - поле 4 - SYVAR10 - поле 5 - E41
(DER, 2, E10, SYVAR.10CH, E40,SYVAR10.3CH,E41)
; чтение записи 10 из файла, открытого на 1-ом канале. Когда операция выполнена,
; содержание полей присваивается переменной, описанной в записи структуры 2.
(RED, 1, 2, 10)
