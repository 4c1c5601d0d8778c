skip-end-only: when the only end of a program is skippable the program is not terminated (GOST 20999 §1.9, decision 3, NC1018, NC1006)
%1
N1 G00 X1.
/N2 M30 (skippable - the reader reads on and finds the end of the file)
