; source: ../shared/corpus/nc110/part5/5.3.2.4-WRT-example.nc (seed section 5.3.2.4)
; expect: origins file ORIG/MP3 with 7 fields IN, CH, LR, CH, LR, CH, LR; record 3 = origin 2.
; expect: after the run: field 3 of record 3 (E45) is increased by 0.5, all other fields of record 3
; are rewritten unchanged; channel 1 is closed.
; Changes: "Е45 = Е45+0.5" is printed with Cyrillic Е; written here with Latin E (decision 2).
; The sandbox (corpus-5.3.2.4-WRT.files.txt) holds ORIG/MP3 with four origins; the files after the
; run show record 3's field 3 at 100.75 (was 100.25) and every other field as it was.
; - определение структуры записи
(DER, 2, E10, SYVAR10.CH, E45, SYVAR11.CH, E46, SYVAR12.CH, E47)
;
; - открытие файла для записи
 (OPN, 1, ORIG/MP3, W)
;
; чтение 3-ей записи (2-ая начальная точка) из файла ORIGIN (поле 3 установлено в Е45)
(RED, 1, 2, 3)
;
E45 = E45+0.5
;
; перезапись после редактирования поля 3
(WRT, 1, 2, 3)
;
; закрытие канала
(CLO, 1)
