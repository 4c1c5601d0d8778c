tape-blank-lines: empty lines and lines of spaces and tabs are not blocks (GOST 20999 §2.1, Table 2 note 2)
%1

N1 G00 X1.
   
	
N2 X2.

N3 M30
