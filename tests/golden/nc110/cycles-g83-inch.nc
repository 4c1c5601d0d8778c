; NC-110 §2.8.9.2 under G70 (§2.8.8), decision 53 ("returns 1 mm above the depth
; reached"): the levels, the depth and the peck I are in inches, the 1 mm re-approach
; stays 1 mm (0.03937 in). The trace is in inches. The tool starts at 0 0 0.
; Hole X1: rapid to X1, rapid to R0.1, feed to -0.9 (peck 1), rapid to 0.1, rapid to
; -0.8606 (-0.9 + 0.03937), feed to -1.8606, rapid to 0.1, rapid to -1.8213, feed to
; the bottom -2, rapid to 0.1.
G70
S500 F10 M3
G83 R0.1 Z-2 I1 K1
X1
G80
