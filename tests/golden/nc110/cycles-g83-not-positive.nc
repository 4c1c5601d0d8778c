; NC-110 §2.8.9.2 (seed lines 3844-3877), decision 53: the increment I must be greater
; than zero, the factor K greater than zero and the minimum J not negative (NC4024 at
; the word). A refused definition should leave no cycle active (as NC4068 does), so the
; holes after it drill nothing and report nothing.
; Expected (ncc check):
;   13:13 I0: the peck increment I 0 must be greater than zero (NC4024);
;   16:13 I-5: the same with -5;
;   19:16 K0: the factor K 0 must be greater than zero (NC4024), naming K, not the
;         "peck increment"; no NC4069 at line 20;
;   22:16 K-0.5: the same with -0.5;
;   24:16 J-1: the minimum peck J -1 must be zero or more (J0 is allowed).
F100 S500 M3
G83 R2 Z-25 I0
X10
G80
G83 R2 Z-25 I-5
X10
G80
G83 R2 Z-25 I5 K0
X10
G80
G83 R2 Z-25 I5 K-0.5
G80
G83 R2 Z-25 I5 J-1
G80
