; An indexing table counts whole indexes, at most 99999 (§2.8.3 L2896-2898; decision 48),
; profile motion-indexing (P, 5 degrees per index). ncc check.
; Expected: N1 P2.5: NC4072 "P2.5 must be a whole number of indexes from -99999 to 99999"
; (6:4); N3 G91 P-0.5 likewise (8:8); N2 P99999 and N4 G91 P-99999 are legal.
; P100000 is beyond the address' range: the static NC2014 (10:4).
N1 P2.5
N2 P99999
N3 G91 P-0.5
N4 P-99999
N5 P100000
