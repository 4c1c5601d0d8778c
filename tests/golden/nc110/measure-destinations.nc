; NC-110 §2.8.12 (formats "G72 axis [axis] [axis] En", "G73 r En", "G74 axis [axis]
; [axis] En", seed lines 4458, 4490, 4522), Table 2.9, decision 55: the E word that
; names where the results go stands only in G72/G73/G74 blocks; it must be of class LR
; with room for all the results; G72/G74 take 1 to 3 axes, G73 its radius r.
; line 17: E40 in a G01 block (NC3033, at E40);
; line 18: G72 without its E word (NC3033, at G72);
; line 19: G72 with no axis (NC3033);
; line 20: G74 with four axes (NC3033);
; line 21: E5 is BY, line 22: E29 is RE: the results need LR (NC2016, at the E word);
; line 23: X and Y need E999 and E1000; this machine has E0..E999 (NC2017);
; line 24: G73 needs E998..E1000 (NC2017);
; line 25: G73 without r (NC3033);
; line 26: §1.2.33 prints "G73 R100 E35" with a capital R: refused like line 25;
; line 28: `Z E32` is Z's value (an E right after an axis letter), E43 the
;   destination (seed line 10217): accepted, as are lines 29-30.
F100
G1 X10 E40
G72 X100
G72 E40
G74 X1 Y2 Z3 A4 E40
G72 X100 E5
G72 X100 E29
G72 X100 Y50 E999
G73 r100 E998
G73 E40
G73 R100 E35
G Z50
G72 Z E32 E43
G74 X1 Y2 Z3 E997
G73 r10 E997
