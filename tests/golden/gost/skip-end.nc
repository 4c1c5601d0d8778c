skip-end: M02 or M30 after a slash ends the program only with block skip off; the reader reads on (GOST 20999 §1.9, §2.7, decision 3, NC1018)
%1
N1 G00 X1.
/N2 M02 (with the switch off the program ends here)
N3 X2.
N4 M02
%2
N1 G00 Y1.
N2 X3. (with the switch off the information ends here) / M30
N3 X4.
N4 M30
