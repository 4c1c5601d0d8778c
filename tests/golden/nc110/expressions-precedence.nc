; expressions-precedence: "the expression is evaluated with the priority of brackets and
; signs" (§2.12 seed L7710; decision 9): * and / before + and -, left to right, one sign
; before an operand, parentheses; blanks anywhere between tokens (L8617 ABS (E42-E41)).
; left to right: 8/4/2 = 1, 2-3-4 = -5
E30=8/4/2
E31=2-3-4
; * before +: 14; parentheses first: 20
E32=2+3*4
E33=(2+3)*4
; a sign before an operand: -6, -5, -6, 2-(-3) = 5, +5
E34=-2*3
E35=-(2+3)
E36=2*-3
E37=2--3
E38=+5
; 10 - 6 + 2 = 6; 2*6/3 = 4
E39=10-2*3+8/4
E40=2*(3+(4-1))/3
; functions bind as operands: 7.5 + 3 = 10.5, 0.5*2+1 = 2
E41=ABS(-7.5)+ABS (2-5)
E42=SIN(30)*2+1
; blanks: 7; numbers written .5 and 1.: 1.5; long constants (L7727): 4.99999876
E43= 1 + 2 * 3
E44=.5+1.
E45=-0.00000124+5
; E parameters as operands: (E32-E31)/E30 = (14+5)/1 = 19
E46=(E32-E31)/E30
(DIS,E30)
(DIS,E31)
(DIS,E32)
(DIS,E33)
(DIS,E34)
(DIS,E35)
(DIS,E36)
(DIS,E37)
(DIS,E38)
(DIS,E39)
(DIS,E40)
(DIS,E41)
(DIS,E42)
(DIS,E43)
(DIS,E44)
(DIS,E45)
(DIS,E46)
