Axes 4. 5. 6. named B W C by the profile (decision 6): 5.3 is axis W, so W2 is a
second W. A subprogram that calls itself is found before the run.
%1
N1 G0 B10 5.3 W2
N2 G71 L5
N3 M30
N4 G79 L5
N5 G71 L5
N6 G70
