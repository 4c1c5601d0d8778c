; words-fraction: a constant has at most the decimals of its format (§1.2.6 seed L371:
; X..D 5.4, R5.4, I/J/K5.4, F5.2, S5.2; decision 13, NC2006); trailing zeros are not
; significant.
; five decimals on an axis, on R and on I: NC2006 (format 5.4)
G0 X1.23456
R1.00001
I-0.00001
; three decimals on F and S: NC2006 (format 5.2)
G1 X1 F1.234
S0.001
; a trailing zero is not significant: no error
G0 X1.23450
G1 X2 F100.50
