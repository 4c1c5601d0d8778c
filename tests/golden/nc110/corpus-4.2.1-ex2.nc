; source: ../shared/corpus/nc110/part5/4.2.1-ex2-process{1,2}.nc (seed section 4.2.1, case 2)
; expect: process 1 completes block N131 when bit 12 of packet SA (an input signal) is 1;
; process 2 runs on, independently.
; Changes: this is process 1; process 2 is lib/MP0/EX2P2 (--process). The closing parenthesis of N131,
; lost in print, is restored; the elisions become moves. The PLC sets SA12 in the input script
; (corpus-4.2.1-ex2.input: SA12=1), given when no process can go on without it (decision 63); without
; it the run stops: no process can go on (corpus-4.2.1-ex2.no-plc). ncc check takes the condition as
; met (the PLC is outside the program: corpus-4.2.1-ex2.check).
N130 G1 X10 F1000
N131(WAI,SA12=1)
N132 G1 X20
M30
