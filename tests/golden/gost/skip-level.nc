skip-level: the slash carries no level number; the NC has one block-skip switch (GOST 20999 §2.7, decision 8, NC1013)
%1
N1 G00 X1.
/1 N2 X2.
N3 X3. /2 Y3.
N4 M30
