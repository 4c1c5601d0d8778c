; Unknown three-letter codes (NC3015 at the code): §2.13 (seed lines 7828-7842) and the codes of
; stdlib/dialects/nc110/three_letter_codes.tsv. The manual itself prints (BBS, LAB2) in the
; threshold example of §2.13.2.4 (line 8619, OCR for BNC); codes are three capital letters (lower
; case is not folded); system variable names and the keyboard codes of chapter 3 (ORA) are not
; program codes. The operands of an unknown code are not read (LAB2 is not defined: no NC3010).
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
(BBS,LAB2)
(BBS, LAB2)
N10 (XYZ)
(URTX,45)
(UR,45)
(urt,45)
(Urt,45)
(TIM)
(TMR,2)
(ORA,1,X10)
()
