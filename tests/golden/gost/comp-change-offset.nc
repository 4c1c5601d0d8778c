comp-change-offset: D and H set one offset number (GOST 20999 §3.3.5, ncc decision 28); a new number while a compensation is active takes effect at once
%
N1 D1 (no compensation active - no event)
N2 G41 (left, radius of offset 1)
N3 D2 (radius 4.25 at once)
N4 D2 (the same number again - nothing changes)
N5 H3 (H sets the same offset number - radius 5)
N6 G01 X10. F100.
N7 G40
N8 D1 (no compensation active - no event)
N9 G43 (length of offset 1)
N10 H2 (length 110 at once)
N11 D3 (D sets the same offset number - length 95)
N12 G40
N13 M30
