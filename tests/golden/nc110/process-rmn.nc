; RMNpq, the path axis q of process p has still to go (§2.10.10, decision 63), in a run of several
; processes: read as the block is evaluated. N1 moves X 100 mm in 6 s; N2, evaluated ahead of that
; motion a block cycle (1 ms) after it started, reads 99.98 mm; N4, after '#', none. Process 2
; (lib/MP0/RMNP2) reads X of process 1 after its dwells, at 1.502 s (75.07 mm left: process 1's move
; started at 0.006 s, its sixth block) and at 4.504 s (25.03 mm), and Y of process 1 (0).
N1 G1 X100 F1000
N2 E30=RMN11
N3 (DIS,"P1 AHEAD ",E30)
N4 # E31=RMN11
N5 (DIS,"P1 AFTER ",E31)
M30
