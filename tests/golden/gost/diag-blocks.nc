diag-blocks: block composition (NC3001-NC3005, NC3007-NC3009)
%
N10 G01 X0 F100
N20 X1 X2 (NC3001 - X twice, with a note at the first)
N30 S100 S200 T1 T2 (NC3001 - S twice, T twice)
N40 G00 G01 X3 (NC3002 - two codes of group a)
N50 G04 G04 P1 (NC3002 - a block-only code without a group letter is its own group)
N60 G90 G91 G17 G18 (NC3002 - groups i and c)
N70 G05 X4 (NC3003 - G05 is not defined)
N80 M12 (NC3004 - M12 is not defined)
N90 S100 M03 M04 (NC3005 - two spindle directions)
N100 M08 M08 (NC3001 - the same code twice)
N110 M07 M08 M09 (NC3005 - M09 cancels M07, reported once)
N120 X5 F100 F200 (NC3009 - per-axis feeds are not enabled)
N115 X6 (NC3007 - lower than the block number before)
N60 X7 (NC3007 - used again, with a note at the first)
:200 G01 X8 (NC3008 - a main block that does not set everything)
:210 G01 G90 G17 X9 F100 S500 M03 T1 (a complete main block)
N220 M30
