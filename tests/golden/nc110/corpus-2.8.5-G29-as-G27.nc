; Variant of corpus-2.8.5-G29 (seed §2.8.5, L3056-3063): N11 selects G27 instead of G29.
; "During a continuous profile (G27-G28) the auxiliary functions M, S and T are not
; allowed." N13 starts the profile (the motion before it, N12, is a rapid) and M05 may
; stand in it; N14 carries S1200 and M13 inside the running profile: NC4053 at 11:1
; (decision 44), and the run stops there (the dry run goes on; no other problem).
N9 (DIS,"ФРЕЗА D=16")
N10 S800 T4.4 M6
N11 G27 G X-235 Y230 M13
N12 Z-10
N13 G1 X75 F500 M5
N14 Y S1200 M13
N15 G3 X-70.477 Y25.65 I J
N16 TMR=2
N17 G1 G4 X-187 Y-295
N18 G Z5
N19 M5
N20 (DIS,"24")
N21 T5.5 M6 S1200
