; Three-letter code operands whose diagnostics must say what is wrong (each block's expected result
; is in its comment; the .out has them). Rules: §2.13, Table 2.9, decisions 2, 3, 14, 19.
; The first block ends the run (M30): the dry run executes none of the blocks below.
M30
"L1" M30
; A pair with its second value missing: NC3018 "the second value of X is missing (a pair is
; written X-300 X300, with a blank)", at the operand.
(DLO,X-300)
; The comma inside a pair (§1.2.41 prints (DSA,1,Z0,Z50,X5 X100)): the same NC3018 at X-300.
(DLO,X-300,X300)
; An empty operand: NC3016 "(UAO) needs an axis letter here: the operand is empty" (and "an
; origin number 0..99 here" on line 14), at the comma before the empty operand.
(UAO,1,)
(UAO,,X)
; Text after the closing parenthesis: NC1028 "a block holds one instruction: words after a
; three-letter code, 'X10'", at the X10.
(URT,45) X10
; A blank inside the code: NC3015 names the code as written, "(U RT) is not a three-letter
; code of the dialect".
(U RT,45)
; An E parameter beyond e_count (E0..E999): NC2017 "E1000 does not exist" alone, no second
; error about the origin number.
(UAO,E1000)
; '*' in an operand (a character of Table 2.1): NC3018 "'E25*2' cannot be an angle of (URT):
; '*2' is left over" (and "'E1*2' cannot be a text or a value of (DIS)"), as for + - /;
; not NC1001.
(URT,E25*2)
(DIS,E1*2)
; The letter O for 0 in a comparand or item: NC3018 with the hint decision 19 promises ("the
; letter O where the digit 0 is meant").
(BGT,O,E2,L1)
(DIS,O)
; O for 0 in an axis value: NC3018 "'XO' cannot be an axis and its value of (UIO)", same hint.
(UIO,XO)
; A sign before an E parameter in an axis operand: NC2018 with the NEG hint, as for the same
; thing in an ISO word (X-E30, decision 14).
(UOT,1,X-E30)
; A blank inside a label or program operand: NC3018 "a label is written without blanks" ("a
; program name is written without blanks" for CLS); decision 3 and the reader's own rule reject
; blanks, as for the label definition "L 1" (NC1024). One NC3018 at each of lines 41-43.
(BNC,L 1)
(EPP,L 1,L1)
(CLS,P 800)
; A blank between E and its index in an item is allowed, as in words (ZE 35, seed line 9150):
; (DIS,E 1) reads E1, no error.
(DIS,E 1)
; Unterminated code: NC1014 "unexpected end of the line in the block" at the end of the line.
(TOF,E11
; A text compared with a shorter CH reference: warning NC3035 'text "OKK" has 3 characters and
; is compared with the 2 characters of SYVAR1.2CH: the rest is not compared'. 17 errors, 1 warning.
(BEQ,SYVAR1.2CH,"OKK",L1)
