; Process 2 of process-asset.nc: FILQ open to write while process 1 tries it.
N1 (OPN,1,FILQ/MP3,W)
N2 (SND,1)
N3 (WAI,1)
N4 (CLO,1)
N5 (SND,1)
M30
