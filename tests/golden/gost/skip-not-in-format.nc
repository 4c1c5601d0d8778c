skip-not-in-format: an NC whose format descriptor has no slash has no block skip (GOST 20999 §9.2, NC1017)
%1
N1 G00 X1.
/N2 X2.
N3 X3. / Y3.
N4 M30
