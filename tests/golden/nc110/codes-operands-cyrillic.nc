; Decision 2 (§2.4.1, Table 2.1): a Cyrillic letter that looks like a Latin one is an error naming
; the Latin letter (NC1027), in three-letter codes too: the manual prints (CTL, Т) with a Cyrillic
; Т (seed line 9499). Expected for each block below: NC1027 "'Т' (U+0422) is Cyrillic; the Latin
; letter 'T' looks the same and is meant here" at the Cyrillic letter (as ncc reports for `Е30 = 28.5`
; and `X10 Y Е31`), and in the code name: (СTL,T) is NC1027 at the Cyrillic С. Each block below
; gives this one error, also in DIS and branch operands (no NC1001, no NC3028): 7 errors in all,
; at column 6 (the Cyrillic letter opening the operand), on line 23 at column 2.
; The first block ends the run (M30): the dry run executes none of the blocks below.
M30
"L1" M30
; Т (U+0422) for T, as printed at line 9499.
(CTL,Т)
; Е (U+0415) for E in an E parameter operand.
(URT,Е25)
; О (U+041E) for O (itself the manual's misprint for 0).
(UAO,О)
; Х (U+0425) for X in an axis operand.
(UIO,Х10)
; Е in an item and in a comparand.
(DIS,Е30)
(BEQ,Е30,1,L1)
; С (U+0421) for C in the code name.
(СTL,T)
