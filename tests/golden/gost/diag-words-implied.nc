diag-words-implied: words with an implied decimal point (NC2004, NC2007, NC2012)
%
N001 G01 X00010000 F1000
N002 X1.5 Y2. (NC2004 - a decimal point without DS in the format)
N003 X125 (NC2007 - X+53 needs exactly 8 digits)
N004 Y123456789 Z123456789 (NC2012 - more than 5 + 3 digits)
N005 F15000 (NC2012 - F031 allows at most 4 digits)
N6 X00020000 (NC2007 - N3 needs exactly 3 digits)
N007 S800 M03 (NC2007 - S4 needs exactly 4 digits)
N008 X123456789 (NC2007 - nor more than 8 digits)
N009 X00030000 Y-1 Z-0001 S0800 (no error)
N010 M30
