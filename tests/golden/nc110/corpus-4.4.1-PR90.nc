; source: ../shared/corpus/nc110/part5/4.4.1-PR{90,98,99,100,101}-process{1,2,3}.nc (seed section 4.4.1)
; expect: PR90 runs in process 1 (selected with SPG, started with START).
; expect: PR90 N1/N2 start PR98 in process 2 and PR99 in process 3; PR99 waits at N1 until PR90
; executes N7 (SND,3).
; expect: PR90 waits at N60 for PR98 N72 (SND,1) and at N61 for PR99 N69 (SND,1); PR98 and PR99 then
; release (REL).
; expect: PR90 N62/N63 start PR100 in process 2 and PR101 in process 3, which run without further
; synchronisation until REL; PR90 ends with N200 M30.
; Changes: this is PR90; the others are lib/MP0/PR98 ... PR101. The elisions become moves on each
; process's own axes; the tool changes and speeds of the first blocks ("T1.1M6S1000F500") become a
; spindle speed and a feed (the default machine has no correctors): S1000 M3 F500 and the like.
; PR100 and PR101 start once PR98 and PR99 released their processes (EXE waits for a free process:
; decision 63; here they are free already).
N1(EXE,2,PR98)
N2(EXE,3,PR99)
N3 S1000 M3 F500
N6 G1 X10 Y10
N7(SND,3)
N8 G1 X20
N60(WAI,2)
N61(WAI,3)
N62(EXE,2,PR100)
N63(EXE,3,PR101)
N64 G1 X0 Y0
N200 M30
