; Process 2 of process-rmn.nc: it reads the path process 1 has to go, at 1.5 s and 4.5 s.
N10 (DLY,1.5)
N11 # E30=RMN11
N12 (DIS,"X AT 1.5 ",E30)
N13 (DLY,3)
N14 # E30=RMN11
N15 E31=RMN12
N16 (DIS,"X AT 4.5 ",E30," Y ",E31)
M30
