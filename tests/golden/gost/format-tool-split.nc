format-tool-split: T04 split 2 + 2 (tool, offset), right-aligned (S-6.5, §3.3.5)
%
N1 T0102 (tool 1, offset 2)
N2 T102 (0102, tool 1, offset 2)
N3 T12 (0012, tool 0, offset 12, warning NC2009)
N4 M02
