; Copy of corpus part4/2.13.5.4-CTL-formats.nc (NC-110 §2.13.5.4, seed lines 16364-16366)
; as printed: the operand of the first block is the Cyrillic letter Т (U+0422). The
; annotations after " - " are dropped.
; Checks (decision 2): the Cyrillic letter that looks like a Latin one is an error that
; names the Latin letter T (NC1027), line 6 column 7; (CTL) is correct.
(CTL, Т)
(CTL)
