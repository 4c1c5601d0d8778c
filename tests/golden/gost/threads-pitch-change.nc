threads-pitch-change: with thread_pitch_change_address = Q, Q is the pitch change per revolution, added by G34 and subtracted by G35 (GOST 20999 §7.4)
%
N1 G90 G00 X10. Z5. S500 M03 (spindle turning)
N2 G34 Z-20. K1.5 Q0.1 (increasing pitch, initial pitch 1.5, plus 0.1 per revolution)
N3 G00 Z5.
N4 G35 Z-20. K1.5 Q0.01 (decreasing pitch, minus 0.01 per revolution, about 1.32 at the end)
N5 M02
