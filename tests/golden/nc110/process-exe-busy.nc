; EXE into a process that still runs a program waits until it is free (decision 63): process 2 runs
; PR100 (--process), and N1 starts PR101 there once PR100 released it (REL), at that time.
N1 (EXE,2,PR101)
N2 G1 X10 F1000
M30
