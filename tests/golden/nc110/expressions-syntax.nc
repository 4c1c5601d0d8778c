; expressions-syntax: the forms of §2.12 (seed L7657-7747; decisions 9 and 10): one sign
; before an operand, the binary operators + - * /, functions of one argument (SIN COS TAN
; ARS ARC ART SQR ABS INT NEG) or two (MOD FEL FEP FEC), in parentheses. NC1014 for a
; stray token, NC3030 for a function used in the wrong form, NC3036 for an unknown one.
; two signs in a row: NC1014 at the second
E30=--3
; ** is not an operator: NC1014 at the second *; ^ is not a character of Table 2.1: NC1001
E31=2**3
E32=2^3
; a function without parentheses: NC3030
E36=SIN 30
; MOD takes two arguments; the manual's OCR form MOD(A/B) (L782) is one: NC3030
E37=MOD(5)
E41=MOD(E1/E2)
; SIN takes one: NC3030; a third argument of MOD: NC1014 at the second ','
E39=SIN(1,2)
E38=MOD(5,2,1)
; not a function of the dialect (SQRT, LOG): NC3036
E40=SQRT(4)
E42=LOG(2)
