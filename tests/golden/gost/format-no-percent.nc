N1 G00 X1. (format-no-percent - a format without the program-start character makes a line starting with it an error)
%
N2 M30
