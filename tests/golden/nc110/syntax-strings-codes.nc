; syntax-strings-codes: an unclosed text in a three-letter code is NC1025, as in the other
; blocks (Table 2.1 seed L1413: '"' is the only delimiter). Expect NC1025 at line 6
; column 6 (from the '"' to the end of the block) and at line 8 column 17; the
; typographic quote of L3969 at line 7 column 6 is not a delimiter: an error naming the
; character ” (U+201D), not a byte.
(DIS,"ABC)
(DIS,”TWIST DRILL D=6)
(BEQ,SYVAR1.2CH,"OK,L)
"L"
