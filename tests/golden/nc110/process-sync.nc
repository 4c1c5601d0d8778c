; When a block of one process takes effect for another (§2.16, decision 63): a block is evaluated up
; to 64 blocks ahead of the motion (machine.look_ahead), so N2 sets SYVAR1 while N1 still moves; '#'
; makes N4 wait for the motion of N3; SA and SK blocks wait without '#' (N6), unless '&' (N8).
; Process 2 (lib/MP0/SYNCP2) shows the clock (TIM0) as each of its waits ends.
N1 G1 X100 F1000
N2 SYVAR1=1
N3 G1 X0
N4 # SYVAR2=1
N5 G1 Y60
N6 SK20=1
N7 G1 Y0
N8 & SK21=1
M30
