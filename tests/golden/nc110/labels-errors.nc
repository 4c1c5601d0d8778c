; labels-errors: a label is 1 to 6 capital letters or digits (Latin or Cyrillic), in
; quotes, unique in its file (§2.4.4 seed L1478-1480; decision 3): NC1024 for a bad
; label, NC3020 for a second definition; a reference is unquoted and must name a label
; of the file (NC3018, NC3010).
"AB"
; defined twice: NC3020, with a note at line 5
"AB" E1=1
; lower case (Latin and Cyrillic), too long (7 Latin, 7 Cyrillic), a blank, a sign,
; empty: NC1024
"ab"
"жук"
"ABCDEFG"
"НАЧАЛОК"
"LAB 1"
"A-1"
""
; references: lower case, quoted, too long (NC3018), not defined (NC3010)
(BNC,Ab)
(BNC,"AB")
(BNC,ABCDEFG)
(BNC,ZZ)
