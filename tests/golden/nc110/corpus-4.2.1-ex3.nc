; source: ../shared/corpus/nc110/part5/4.2.1-ex3-process{1,2}.nc (seed section 4.2.1, case 3)
; expect: process 1 completes block N147 when byte 250 of packet K (a PLC logic signal) is 8;
; process 2 runs on, independently.
; Changes: this is process 1; process 2 is lib/MP0/EX3P2 (--process). The elisions become moves. The
; PLC writes SK250 in the input script (corpus-4.2.1-ex3.input): first 7, which does not meet the
; condition, then 8, which does (SK's own format is BY: SK250 is byte 250).
N146 G1 X10 F1000
N147(WAI,SK250=8)
N148 G1 X20
M30
