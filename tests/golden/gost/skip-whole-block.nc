skip-whole-block: a slash before N, before the colon or first in the block makes the whole block skippable (GOST 20999 §2.7, Table 2, decision 8)
%1
N1 G00 X1.
/N2 X2. (skipped with the switch on)
/G00 Y5. (no block number - the slash is first, the whole block)
/ N3 Z1. (spaces after the slash)
/:4 G90 G17 G00 X4. F100 S100 M03 T1 (a main block)
N5 M30
