diag-tool-split: T = 2 tool digits + 2 offset digits, right-aligned (NC2009)
%
N1 T0102 M06 (tool 1, offset 2)
N2 T102 (right-aligned as 0102 - tool 1, offset 2)
N3 T03 (NC2009 - right-aligned as 0003 - tool 0, offset 3)
N4 T0 (tool 0, offset 0 - no warning)
N5 M30
