bad-leader-only: a file of leader text only, no program start anywhere
set-up notes: fixture 12, tool list below
T1 end mill D10
N1 G00 X1. M30 (looks like a block, but without a program start it is leader)
