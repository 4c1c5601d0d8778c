; NC-110 §2.8.9 note 4 (seed lines 3712-3713: "a new canned cycle cannot be programmed
; without closing the previous one with G80"), Table 2.4, decision 52: with a cycle
; active, a new cycle (another or the same code), G02, G03, G06, G33, G34, G72, G73,
; G74 and G79 are refused (NC4051) at the G word; after G80 a new cycle is accepted.
F100 S500 M3
G81 R5 Z-10
G82 R5 Z-10
G81 R5 Z-10
G2 X10 Y0 I5 J0
G3 X10 Y0 I5 J0
G06 X10 Y5
G33 Z-10 K1
G34 Z-10 K1
G72 X10 E40
G73 r10 E40
G74 X10 E40
G79 X10
G80
G82 R5 Z-10
X10
G80
