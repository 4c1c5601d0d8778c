end-m02-feed: after M02 F is unset (ncc decision 19) - the next program's first feed move must program F again (NC4001)
%1
N1 G01 X10. F100.
N2 M02
%2
N1 X20. (no F since the reset)
N2 M30
