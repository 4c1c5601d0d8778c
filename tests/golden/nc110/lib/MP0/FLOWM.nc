; FLOWM (cls-modal): reads E30 set by the caller, sets E31, leaves G01, G91,
; F200 and a temporary origin X100 in force for the caller.
E31=E30*2
G1 G91 X5 F200
(UOT,0,X100,Y0)
