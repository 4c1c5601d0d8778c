; epp-undefined: the labels of (EPP,L1,L2) must be defined in the file (NC3010)
; (decision 22, decision 3); labels are written unquoted (NC3018), two of them
; (NC3016, NC3017) (§2.13.2.3 L8503-8518). The range's first label is undefined
; here; an undefined last label: epp-undefined-end.
"A" E1=1
(EPP,XX,A)
(EPP,"A","A")
(EPP,A)
(EPP,A,A,A)
M30
