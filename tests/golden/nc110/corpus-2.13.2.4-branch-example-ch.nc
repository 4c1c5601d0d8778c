; corpus-2.13.2.4-branch-example-ch: the block of corpus part4/2.13.2.4-branch-
; example-CH.nc (§2.13.2.4, seed L8595-8597 / L15855): "(BEQ,SYVAR2.3CH,"ABC",
; END) jumps to END if the three characters of SYVAR2 are ABC" (bytes 2-4).
; Run twice: with "ABD" stored (not taken), then with "ABC" (taken).
; Changed: the annotation is dropped; the stores (format of §2.10.5 L5107),
; the label END, the messages and M30 are added.
SYVAR2.3CH="ABD"
(BEQ,SYVAR2.3CH,"ABC",END)
(DIS,"NOT TAKEN WITH ABD")
SYVAR2.3CH="ABC"
(BEQ,SYVAR2.3CH,"ABC",END)
(DIS,"NOT REACHED")
"END" (DIS,"AT END ",SYVAR2.3CH)
M30
