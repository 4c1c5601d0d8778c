; source: ../shared/corpus/nc110/part5/4.4.2-PROG1{0,1,2}-process{1,2,3}.nc (seed section 4.4.2, table 4.1)
; expect: three independent (unsynchronised) programs, each selected in its process from the keyboard
; ("P3", then SPG,<name>) and started with START: PROG10 in process 1, PROG11 in 2, PROG12 in 3.
; Changes: this is PROG10; PROG11 and PROG12 are lib/MP0/PROG11 and lib/MP0/PROG12, selected with
; --process 2=PROG11 --process 3=PROG12 as SPG selects them. The tool changes of the first blocks
; ("T1.1M6S3000") become spindle speeds (the default machine has no correctors); the elided arc of
; N4 becomes a quarter circle; the elisions are left out. PROG12 ends without M30, as printed: its
; process ends with its last block. The processes run side by side, each on its own axes, in the
; order of their time (decision 63).
N1 S3000 M3
N2 G0 X0 Y0
N3 G1 X100 Y50 F500
N4 G2 X150 Y0 I100 J0
N99 G1 X10 Y0
N100 G0 X0 Y0 M30
