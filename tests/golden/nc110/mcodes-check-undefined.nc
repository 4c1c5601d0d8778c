; M codes not in Table 2.3 (seed lines 1773-1833; stdlib/dialects/nc110/m_codes.tsv): each of the
; 76 numbers M00-M99 the table lacks is NC3004 at its word, also beside table codes and in the
; one-digit form. (Table 2.3 is "purely indicative", lines 1884-1890: the machine logic may add or
; remove M codes; the default machine has exactly the table.)
; Expected: NC3004 "M20 is not defined and the machine profile does not define it" at each word (a
; profile may add codes with nc110.tables.m_codes: mcodes-machine-table); M5 is M05, no error; 79
; errors: the 76 numbers, M15 in "M5 M15", M20 and M21 beside M03 M08 M06.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
M15
M16
M17
M18
M20
M21
M22
M23
M24
M25
M26
M27
M28
M29
M31
M32
M33
M34
M35
M36
M37
M38
M39
M46
M47
M48
M49
M50
M51
M52
M53
M54
M55
M56
M57
M58
M59
M61
M62
M63
M64
M65
M66
M67
M68
M69
M70
M71
M72
M73
M74
M75
M76
M77
M78
M79
M80
M81
M82
M83
M84
M85
M86
M87
M88
M89
M90
M91
M92
M93
M94
M95
M96
M97
M98
M99
; One digit: M5 is M05 (in the table, no error), M15 is not.
M5
M15
; Beside table codes.
M03 M20 M08
M21 M06
