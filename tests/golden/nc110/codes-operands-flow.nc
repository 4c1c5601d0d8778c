; Operands of the flow codes RPT ERP CLS EPP BNC BGT BLT BEQ BNE BGE BLE (§2.13.2, seed lines
; 8329-8621; stdlib/dialects/nc110/three_letter_codes.tsv): for each code a correct block (no error),
; a missing operand (NC3016 at the closing parenthesis), an extra operand (NC3017 at it), operands
; of the wrong kind (NC3018: a label where a count is needed, an expression, the letter O for 0, a
; quoted or lower-case label, a bad program name) and an E parameter of the wrong class (NC2016;
; Table 2.9, lines 7761-7827: the RPT count is BY E0-E9). A comparand may be an E parameter of
; any class. Labels: 1 to 6 capitals and digits, unquoted (decision 3); program names: 1 to 6
; capitals and digits, a letter first, /DEVice of 2 or 3 (§2.13.2.2, lines 8428-8434).
; (ERP) or (RPT,..) alone is NC3021. A RPT with a wrong operand still opens its loop, so the wrong
; RPTs below, which have no ERP, are NC3021 too (and the fourth open, NC3022); (ERP,1) closes (RPT,E10).
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
"L1" M30
"L2" M30
"2" M30
; RPT (§2.13.2.1): a count 0..99; ERP: no operand.
(RPT,E9)
(ERP)
(RPT,0)
(ERP)
(RPT)
(RPT,2,3)
(RPT,LAB)
(RPT,O)
(RPT,E1+1)
(RPT,100)
(RPT,2.5)
(RPT,E10)
(ERP,1)
; CLS (§2.13.2.2): a program name with an optional device.
(CLS)
(CLS,P800,P900)
(CLS,800)
(CLS,p800)
(CLS,PROGRAM)
(CLS,"P800")
(CLS,P800/M)
(CLS,P800/MP2/X)
; EPP (§2.13.2.3): two labels.
(EPP,L1,L2)
(EPP,L1,2)
(EPP)
(EPP,L1)
(EPP,L1,L2,L1)
(EPP,"L1",L2)
(EPP,L1,LABEL12)
; BNC (§2.13.2.4): one label.
(BNC,L1)
(BNC,2)
(BNC)
(BNC,L1,L2)
(BNC,"L1")
(BNC,l1)
; BGT BLT BEQ BNE BGE BLE (§2.13.2.4): two values to compare (constants, E parameters of any
; class, memories, system variables, texts for BEQ/BNE) and a label.
(BGT,E1,123,L1)
(BLT,E30,0.2,L1)
(BEQ,SYVAR1.2CH,"OK",L1)
(BNE,E10,E25,L1)
(BGE,SA3,1,L1)
(BLE,UOV,TMR,2)
(BGT)
(BGT,E1)
(BGT,E1,E2)
(BGT,E1,E2,L1,L2)
(BGT,E1+1,E2,L1)
(BLT,E1,E2)
(BLT,E1,E2,L1,5)
(BLT,E1,E2-1,L1)
(BLT,E1,E2,"L1")
(BEQ,E1,E2)
(BEQ,E1,E2,L1,5)
(BEQ,E1,E2-1,L1)
(BEQ,E1,E2,"L1")
(BNE,E1,E2)
(BNE,E1,E2,L1,5)
(BNE,E1,E2-1,L1)
(BNE,E1,E2,"L1")
(BGE,E1,E2)
(BGE,E1,E2,L1,5)
(BGE,E1,E2-1,L1)
(BGE,E1,E2,"L1")
(BLE,E1,E2)
(BLE,E1,E2,L1,5)
(BLE,E1,E2-1,L1)
(BLE,E1,E2,"L1")
