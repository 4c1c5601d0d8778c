; syntax-leading-errors: the leading fields stand in the order '/', "LABEL", N, '#'/'&'
; (§2.4.4 seed L1461-1464 "in the mandatory order", L1469 '/' in the first position,
; §2.16 L10736 '#' after the block number). NC1023 for each field out of place; N has at
; most four digits (§1.2.6 L371 "N4": NC2012).
; label after N: column 4
N5 "L1" G1 X1 F100
; N after '#': column 3
# N5 G0 X1
; '#' and '&' together: column 6
N5 & # E1=1
; '/' not first: column 4
"A"/N5 E1=1
; a second label: column 4
"C""D" E1=1
; a second block number: column 4
N5 N6 E1=1
; '#' without an instruction: column 4
N5 #
; five digits: N12345
N12345 E1=1
