; Process 2 of process-text-write.nc: it writes a text once its move has ended.
N1 G1 Y10 F600
N2 # SYVAR0.1CH="A"
M30
