; corpus-2.13.2.4-branch-example-threshold: the threshold example of §2.13.2.4
; (seed L8599-8620; listed in the corpus digest as missing from part4), as
; printed: "jump to LAB1 if E42 = E41, comparing their difference with a
; threshold (with BLT)".
; Expected (ncc check): the label LAB is not defined (NC3010; the annotation
; says LAB1), and BBS is not a three-letter code (NC3015; BNC is meant).
; Changed: the annotations after E43=0.0001 and after the BLT block are dropped.
E42=0.021
E41=0.015
E47=0.0015
E43=0.0001
"LAB2" E41=E41+E47
E44= ABS (E42-E41)
(BLT, E44, E43, LAB)
(BBS, LAB2)
"LAB1" (DIS, E41)
