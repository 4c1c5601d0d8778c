; source: ../shared/corpus/nc110/part5/4.2.1-ex4-process{1,2}.nc (seed section 4.2.1, case 4)
; expect: E8 = 10.3+20.7 = 31; SYVAR2 = 31 in N152 of process 1; process 2 completes block N121 when
; SYVAR2 becomes 31.
; Changes: this is process 1; process 2 is lib/MP0/EX4P2 (--process). The elisions become moves, and
; N154 shows SYVAR2. Process 2 waits from N121 until N152 writes SYVAR2, and goes on from that time.
N150 G1 X10 F1000
N151 E8=10.3+20.7
N152 SYVAR2=E8
N153 G1 X20
N154 (DIS,SYVAR2)
M30
