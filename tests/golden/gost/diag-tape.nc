diag-tape: programs on the medium (NC1006, NC1015, NC1016, NC1018, NC1020, NC1021)
%%123456789 (NC1016 - nine digits)
N1 G01 X1 F100
/N2 M02 (NC1018 - an end in a skippable block)
N3 X2 /M30 (NC1018 - an end in the skippable rest of a block)
%%7 (NC1006 for the program above, NC1021 for the second percent sign)
G00 X3 (NC1015 - the first block has no number)
N4 M02
%1 (NC1020 - no blocks before the next program start)
%2
N5 G00 X0 (NC1006 - the file ends before M02 or M30)
