(translate-rounded-rate-refused: a dwell of 0.125 s is Q12.5 in pp's 10 ms: Q12 or)
(Q13 is another dwell by 4 %, so it is refused: NC4096)
G21 G90 G94
G01 X10. F100.
G04 P0.125
M30
