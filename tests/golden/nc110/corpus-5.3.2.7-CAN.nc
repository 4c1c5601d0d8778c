; source: ../shared/corpus/nc110/part5/5.3.2.7-CAN-example.nc (seed section 5.3.2.7)
; expect: file PUNTXZ on device MP3 is deleted and its memory freed.
; The sandbox holds PUNTXZ/MP3 and PUNTXZ/MP1: only the first is deleted.
(CAN, PUNTXZ/MP3)
