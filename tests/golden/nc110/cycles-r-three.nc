; NC-110 §2.8.9 format "G8X [R1[R2]] ..." (seed lines 3533-3549): a cycle takes at most
; two R words. Expected: an error at the third R word (line 5, column 18: R5), the
; cycle not stored. (The digest /tmp/nc110-motion.md §10 E19: ">2 R" is an error.)
F100
G81 R-10 R2 Z-36 R5
X1
G80
