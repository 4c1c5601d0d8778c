; source: ../shared/corpus/nc110/part5/5.3.2.1-OPN-example.nc (seed section 5.3.2.1)
; expect: file FILQ on device MP3 is opened on channel 1 with access W (read and write/edit).
; Changes: the annotation " - Открыть файл FILQ на канале 1 для чтения и записи." printed beside
; the block is left out. The sandbox holds FILQ/MP3.
(OPN, 1, FILQ/MP3, W)
