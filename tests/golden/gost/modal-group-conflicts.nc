modal-group-conflicts: two codes of one modal group must not share a block (GOST 20999 §2.5, Table 4 groups u c i k l, NC3002)
%
N1 G71 G70 (units)
N2 G17 G19 (plane)
N3 G90 G91 (absolute / incremental)
N4 G93 G95 (feed mode)
N5 G96 G97 (spindle mode)
N6 G18 G18 (the same code twice)
N7 M30
