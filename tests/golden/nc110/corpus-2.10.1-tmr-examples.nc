; corpus-2.10.1-tmr-examples: copy of corpus/nc110/part3/2.10.1-tmr-examples.nc (§2.10.1
; seed L4935-4966). Expect: TMR = 12.5 sets a dwell of 12.5 s (G94); E32 = 13.4 then
; TMR = E32 a dwell of 13.4 s; the dwell runs at the end of G04 blocks. Corrected: the
; manual's Russian annotations after the code are dropped; Cyrillic Т in TMR and Е in E32
; made Latin (NC1027 otherwise, syntax-homoglyphs.nc). Added: a G04 after each TMR and
; DIS of E32: dwell 12.5, dwell 13.4.
TMR = 12.5
G4
E32 = 13.4
TMR = E32
G4
(DIS,E32)
