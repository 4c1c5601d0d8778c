modal-inverse-time-errors: in G93 every feed move needs its own F (GOST 20999 Table 5 G93, ncc decision 26, NC4014)
%
N1 G93 G01 X10. F2. (correct)
N2 X20. (no F - an error)
N3 G02 X30. Y10. J10. (an arc without F - an error)
N4 G00 X0 (a rapid needs no F)
N5 G94 G01 X5. F100. (per minute - F is modal again)
N6 X6.
N7 G93 X10. (G93 again without F in the block - an error)
N8 M30
