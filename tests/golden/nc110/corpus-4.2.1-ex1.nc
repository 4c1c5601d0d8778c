; source: ../shared/corpus/nc110/part5/4.2.1-ex1-process{1,2}.nc (seed section 4.2.1, case 1)
; expect: process 2 completes block N106 (goes on after (WAI,1)) when process 1 executes (SND,2) in N21.
; Changes: this is process 1; process 2 is lib/MP0/EX1P2, started with the run (--process). The
; dotted elisions become moves on each process's own axis; "M22" (OCR) is read as N22; M30 ends each.
N20 G1 X10 F1000
N21(SND,2)
N22 G1 X20
M30
