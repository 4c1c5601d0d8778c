; branches-text-errors: texts compare only with texts and only with BEQ/BNE;
; two kCH references must have one length; two quoted texts compare to a
; constant result (decision 23; codes digest §2.6 "string vs number is an S
; error"; NC3032). One error per line.
"L" (BEQ,SYVAR1.2CH,1,L)
(BEQ,E1,"OK",L)
(BEQ,SYVAR1.2CH,E1,L)
(BNE,SYVAR1.2CH,SA3,L)
(BGT,SYVAR1.2CH,"OK",L)
(BLT,"A","B",L)
(BGE,SYVAR1.2CH,SYVAR1.2CH,L)
(BLE,SK7.3CH,"RIF",L)
(BEQ,SYVAR1.2CH,SYVAR5.3CH,L)
(BEQ,"A","A",L)
M30
