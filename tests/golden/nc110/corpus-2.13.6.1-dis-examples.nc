; corpus-2.13.6.1-dis-examples: copy of corpus part4/2.13.6.1-DIS-examples.nc
; (§2.13.6.1, seed L9604-9615): "(DIS, "ЭТО ПРИМЕР")" shows the message,
; "(DIS, 100)" the constant.
; Expected (decision 37): messages "ЭТО ПРИМЕР" and "100".
; Not supported yet: GTL. Removed: the examples 1) (DIS, "с1=",с1) and
; 2) (DIS, "l2=",l2), which show GTL elements (a circle's centre and radius, a
; line's distance and angle); the manual's с1 is a Cyrillic с (see
; dis-unsupported).
(DIS, "ЭТО ПРИМЕР")
(DIS, 100)
