diag-words: words read by the default format descriptor, with the decimal sign (NC2001-NC2006, NC2012)
%
N1 G01 X0 F100
N2 L5 O7 E3 (NC2001 - addresses the format does not describe)
N3 X Y- Z. (NC2002 - no digits)
N4 F-5 (NC2003 - F051 has no sign)
N5 G+1 M-3 (NC2003 - non-dimension words carry no sign)
N6 G1.5 S100. (NC2004 - non-dimension words are integers)
N7 X123456. Y-0123456.7 Z123456 (NC2005 - six integer digits, a leading zero does not count)
N8 X1.2345 Y.00010 (NC2006 - four significant fraction digits)
N9 X1.2500 Y00012345.000 (no error - insignificant zeros do not count)
N10 S12345 T00001 M100 G123 (NC2012 - more digits than the format allows)
N11 D123 H001 (NC2012 - the digits as written count)
N-12 X1 (NC2003 - a signed block number)
N13 M30
