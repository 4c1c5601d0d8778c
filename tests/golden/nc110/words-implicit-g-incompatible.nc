; words-implicit-g-incompatible: a code given by an E parameter must be compatible with
; the block's other G words (Table 2.4; decisions 1 and 15): E1 = 2 gives G02 beside G00,
; two codes of class a: NC3013 when the block runs (line 7).
E1=2
G0 X1
; error here
GE1 G0 X2
