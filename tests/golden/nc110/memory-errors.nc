; memory-errors: static checks of memory references (§2.10.4-§2.10.5, Table 2.7 seed
; L5117-5200; decision 17). A text longer than its nCH: NC3031. A number into a text
; reference, a text in an expression, a text reference of another length, a non-ASCII
; character: NC3032. A count outside 1..32 or an unknown format: NC3030. An index past
; the end of the memory (SA 1024 bytes = bits 0..8191, SK 1024, SYVAR 200): NC2014.
SYVAR1.3CH="ABCD"
SK7.CH="AB"
SYVAR1.3CH=5
E1=SYVAR1.3CH
SK1.3CH=SYVAR1.2CH
SK1.3CH=SYVAR1.BY
SYVAR1.CH="Ж"
E1="A"
SYVAR1.33CH="A"
SYVAR1.0CH="A"
SYVAR1.XX=1
SYVAR25.LR=1
E1=SYVAR200
SA8192=1
SK1023.IN=1
SK1022.3CH="A"
(DIS,SYVAR50.LR)
