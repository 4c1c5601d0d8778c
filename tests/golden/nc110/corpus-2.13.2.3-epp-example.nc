; corpus-2.13.2.3-epp-example: copy of corpus part4/2.13.2.3-EPP-example.nc
; (§2.13.2.3, seed L8521-8531): "N150(EPP,START,END) - the system executes
; blocks N25 to N100"; afterwards "the program continues from the block after
; the EPP".
; Expected: N20, N25, N50, N60, N100, N110 in sequence; then through N150 the
; range N25 ... N100 (both labelled blocks included) again; then N160.
; Changed: the annotations after the blocks are dropped; the manual's lines of
; dots are comments, and the blocks they stand for are supplied as messages
; (N20, N50, N110, N160) and a move (N60 G X60); the labelled blocks N25 and
; N100, empty in the print, get messages so that the trace shows them; M30 added.
;..........
N20 (DIS,"N20")
"START"N25 (DIS,"N25")
;..........
N50 (DIS,"N50")
;..........
N60 G X60
"END"N100 (DIS,"N100")
;..........
N110 (DIS,"N110")
N150(EPP,START,END)
;..........
N160 (DIS,"N160")
N170 G X0 M30
