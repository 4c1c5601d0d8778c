; source: ../shared/corpus/nc110/part5/4.3-PROG9{1,2,3}-process{1,2,3}.nc (seed section 4.3)
; expect: PROG91 runs in process 1; N1/N2 start PROG92 in process 2 and PROG93 in process 3.
; expect: process 2 runs to N15 and waits at N16 until process 1 executes N24 (SND,2); process 3 waits
; at N1 until process 1 executes N35 (SND,3).
; expect: process 2 waits at N40 until bit 10 of packet SA is 1; process 3 waits at N20 until
; SYVAR1 = 10 (set by process 1 in N59/N60).
; expect: process 1 waits at N66/N67 for restarts from process 2 (N85) and process 3 (N80); the three
; then go on at N68, N86, N81.
; expect: process 1 waits at N77/N78 for N99 (process 2) and N94 (process 3); processes 2 and 3 release
; (REL); process 1 goes back to START and starts the cycle again.
; Changes: this is process 1; PROG92 and PROG93 are lib/MP0/PROG92 and lib/MP0/PROG93. The elisions
; and the placeholders ("T1.1M6S...F...", "GXY", "GX....Y....Z..") become moves on each process's own
; axes, without tool changes. The endless cycle ends after two: N99/N100 count the cycles in E1 where
; the manual jumps back always (BNC). PROG93's "N20(WAI,SYVAR,1)" (OCR) is read as (WAI,SYVAR1=10),
; as the text says; PROG92's "M100(REL)" as N100(REL). The PLC sets SA10 in the input script
; (corpus-4.3-PROG91.input). In the second cycle EXE starts PROG92 and PROG93 again in the processes
; their REL freed; SYVAR1 and SA10 still hold, and processes 2 and 3 go on at once.
"START"
N1(EXE,2,PROG92)
N2(EXE,3,PROG93)
N3 G1 X10 F1000
N4 G1 X20 Y10
N24(SND,2)
N35(SND,3)
N59E5=10
N60SYVAR1=E5
N66(WAI,2)
N67(WAI,3)
N68 G1 X30
N76 G1 X0 Y0
N77(WAI,2)
N78(WAI,3)
N99 E1=E1+1
N100(BLT,E1,2,START)
M30
