; What a process cannot do (decision 63), each stopping the run with NC4089 at its block; the
; operator's answer picks the case: 1 EXE into its own process (process-errors), 2 SND to process 3 of
; a machine of two processes (.snd, processes-2.toml), 4 WAI for itself (.own); and 3 SND to a
; process that runs no program: it waits for ever, so no process can go on (.idle, NC4090).
N1 (INP,"CASE ",E1)
N2 (BEQ,E1,2,SND)
N3 (BEQ,E1,3,IDLE)
N4 (BEQ,E1,4,OWN)
N5 (EXE,1,PROG1)
M30
"SND" (SND,3)
M30
"IDLE" (SND,3)
M30
"OWN" (WAI,1)
M30
