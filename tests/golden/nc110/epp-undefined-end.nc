; epp-undefined-end: an undefined last label of (EPP,L1,L2) is NC3010 at that
; label (line 5 col 8), and nothing else: with a static error there is no run.
"A" E1=1
; YY is undefined
(EPP,A,YY)
M30
