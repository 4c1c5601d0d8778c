m-several: several M codes in one block (GOST 20999 §2.2) act in the order written within their timing (Table 7); the end function comes last
%
N1 G00 X1. S300 M08 M03 M07 M10 (all before the move, in written order)
N2 X2. M59 M49 M11 (before, in written order)
N3 X3. M58 M09 M48 (all after the move, in written order)
N4 X4. T1 M05 M10 M06 M49 (M10 M49 before, M05 M06 after)
N5 X5. M09 M03 (M03 before, M09 after)
N6 X6. M30 M05 (M05 after the move, the end of information last although written first)
