; NC-110 §2.8.9 (format, seed lines 3533-3555; note 1), decision 51: what the block of a
; canned cycle may not hold (NC4068). Each refused definition leaves no cycle active,
; so the next definition needs no G80 (lines 13-15 run clean).
; line 9: no axis word, so no depth and no drilling axis;
; line 10: a second axis word (the holes' positions come in the following blocks);
; line 11: the bottom Z-5 above R1 -10 (the Fig. 2.28 misprint);
; line 12: the bottom equal to R1 (not below it).
F100
G81 R5
G81 R5 X1 Z-10
G82 R-10 Z-5
G83 R-10 Z-10 I2
G81 R5 Z-10
X1
G80
