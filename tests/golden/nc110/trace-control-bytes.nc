; Memory never written holds zeros: a field or a message that shows it shows them
; escaped (\u0000) in every trace format and on --screen, never as raw bytes (issue 17).
(SCR,ON)
(DEF,1,2,,SYVAR10.3CH)
(OUT)
(DIS,SYVAR10.2CH,"|")
M30
