; epp-cut-loop-start: a range that starts in an RPT body and ends after the loop
; cuts the loop: NC3024 (decision 22: "a range must hold whole RPT loops").
; One error is expected at the EPP operand H.
(RPT,2)
"H" E3=1
(ERP)
"K" E4=1
(EPP,H,K)
M30
