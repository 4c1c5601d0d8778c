; dis-errors: DIS needs at least one item (NC3016); an item is a quoted text, a number, an
; E parameter, SA/SK/SYVAR within its memory (SYVAR200: NC2014) or a readable system
; variable (NC3028, NC3029), never an expression (NC3018) (§2.13.6.1 L9590-9603; decision 19).
(DIS)
(DIS,E1+1)
(DIS,XYZ)
(DIS,JOG)
(DIS,SYVAR200)
M30
