; NC-110 §2.8.9.2, decision 53: a hole that would take more than 10000 pecks is refused
; (NC4043) before it is drilled, with the number of pecks it would need.
; Expected (ncc check):
;   11:1 canned cycle G83 would need 27000 pecks of 0.001 to reach the bottom; at
;        most 10000 (chip breaking: 27 mm in pecks of 0.001);
;   14:1 ... 26000 pecks of 1.001 ... (chip unloading, K1: the first peck 1.001 to 0.999,
;        then each peck gains 0.001 on the 1 mm the tool comes back: 1 + 25999 pecks).
; `ncc run` should stop at line 11 without tracing 10000 pecks first.
F100 S500 M3
G83 R2 Z-25 I.001
X10
G80
G83 R2 Z-25 I1.001 K1
X20
G80
