; words-ranges: a constant must lie in its address' range (§1.2.6 seed L371 formats,
; §2.7 L1687-1767; decision 13, NC2014); F and S are at least 0.01; G, M and H are
; whole numbers of at most two digits without a sign (NC2015, NC2012, NC2003); H takes
; 0..99 and does nothing (decision 12, NC4025 warning).
; ranges: X 5.4, F 5.2, S 5.2, H2
G0 X100000
G0 Y-100000
G1 X1 F0
G1 X1 F-5
S100000
S0
H100
H-1
; codes: whole numbers, two digits, no sign
G1.5 X1
M3.5
M100
G001 X1
M-3
G+1 X1
; in range: no error; H5 is only a warning
G0 X99999.9999 Y-99999.9999
G1 X1 F0.01
H5
