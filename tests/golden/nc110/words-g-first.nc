; words-g-first: the G words come after the block number and before every other word
; (§2.8 seed L1896-1899, NC3012); G has at most two digits (L1896-1897, NC2012); only
; the decoded codes of Table 2.2 exist (L1899-1900, NC3003); at most four M words
; (L1889-1890) and eight axes (L2042) in a block (NC3014).
; G after an axis word and after F: NC3012 at the G
X10 G1
F100 G1 X1
; an implicit G after an operand: NC3012
G0 X1 GE5
; three digits: NC2012; G07 is not a code of Table 2.2: NC3003
G001 X1
G7 X1
; (a rapid ends the G27 profile the feed moves above began: M words may follow)
G0 X0
; five M words: NC3014 at the fifth
M3 M8 M10 M41 M60
; nine axes: NC3014 (the machine has nine: nc110.axes = XYZABCUVW)
G0 X1 Y1 Z1 A1 B1 C1 U1 V1 W1
; in order, eight axes, four M words, two G words: no error
N5 G0 G90 X2 Y2 Z2 A2 B2 C2 U2 V2
M3 M8 M10 M41
