bad-truncated: the file was cut inside a word, without a final LF, before M02 or M30 (GOST 20999 §1.9, NC2002, NC1006)
%1
N1 G90 G00 X10. Y10.
N2 G01 X20. F100
N3 X30. Y-