; memory-text: <n>CH holds n characters, one ASCII byte each, n = 1..32, 1 when omitted
; (Table 2.7 seed L5120-5139; decision 17); a shorter text is padded with blanks.
; SK7.3CH="RIF" (L5074) writes bytes 7-9 of SK.
SK7.3CH="RIF"
(DIS,SK7.3CH)
(DIS,SK7.BY)
; a shorter text: "AB" and three blanks (bytes 11-15: 65 66 32 32 32)
SK11.5CH="AB"
(DIS,"[",SK11.5CH,"]")
(DIS,SK15.BY)
; copy between references of one length
SK20.5CH=SK11.5CH
(DIS,"[",SK20.5CH,"]")
; SYVAR16.3CH = "ABC" (L5107): byte 16 = 65
SYVAR16.3CH = "ABC"
(DIS,SYVAR16.BY)
; no count: one character; blanks inside the reference (L5142 SYVAR 1.4CH)
SK7.CH="Z"
(DIS,SK7.3CH)
SYVAR 1.4CH="ABCD"
(DIS,SYVAR1.4CH)
; the longest text: 32 characters
SK100.32CH="ABCDEFGHIJKLMNOPQRSTUVWXYZ012345"
(DIS,SK131.CH)
