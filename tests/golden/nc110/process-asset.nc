; ASSET files in a run of several processes (decision 63): the open files are the run's, each
; process's channels its own. Process 2 (lib/MP0/ASSETP2) opens FILQ to write on its channel 1 and
; waits; process 1 then opens it to read on its own channel 1: code 7 (file already open), which
; ERR=1 lets the program see in IOSTA. Once process 2 closed it, the same OPN works.
N1 (WAI,2)
N2 ERR=1
N3 (OPN,1,FILQ/MP3)
N4 E1=IOSTA
N5 (DIS,"IOSTA ",E1)
N6 (SND,2)
N7 (WAI,2)
N8 (OPN,1,FILQ/MP3)
N9 E1=IOSTA
N10 (DIS,"IOSTA ",E1)
N11 (CLO)
M30
