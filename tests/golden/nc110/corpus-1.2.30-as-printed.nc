; corpus-1.2.30-as-printed: corpus/nc110/part1/1.2.30-assignment-blocks-example-2.nc as
; printed (§1.2.30 seed L802): the first line is two blocks merged by the text extraction,
; with a blank in the label. Expect: the label "LAB 1" is invalid (NC1024, a label has no
; blanks, §2.4.4) and the second '=' starts another assignment (NC1028, decision 6).
"LAB 1" E51 = -0.00000124 +5/E35 = FEL(37,1)
E7 = 81
E10 = 1
E25 = E25 + 30
