skip-rest-of-block: a slash inside a block makes the rest of the block skippable (GOST 20999 Table 2, decision 8)
%1
N1 (the words before the slash always run) G00 X1. / Y1.
N2 X2. S200 / Y2. M03
N3 / X3.
N4 X4. / Y4. / Z4.
N5 M30
