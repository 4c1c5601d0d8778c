; corpus-2.10.7-tot-example: copy of corpus/nc110/part3/2.10.7-tot-example.nc (§2.10.7 seed
; L5258-5275). Expect: N230 shows, in hours, the time to machine a batch of 75 parts:
; TOT0 = TIM0 - TIM1 the cycle time of one part (s), TOT1 = TOT0*E1 for the batch (s),
; TOT2 = TOT1/3600 (h). Corrected: N10 "E=75" lost its index: E1=75 (E1 is used in N210);
; OCR TIMO/TOTO = TIM0/TOT0; annotations dropped. The elided blocks are supplied: N50 G1
; X500 at the F500 of N40 (60 s, decision 50; N40 XY rapids to where the tool is, no
; time; T2.2 M6 takes no time): TOT0 = 60, TOT1 = 4500, TOT2 = 1.25 h.
N10 E1=75
N20 # TIM1=TIM0
N30 T2.2 M6
N40 XY S2000 F500 M13
N50 G1 X500
N200 # TOT0=TIM0-TIM1
N210 TOT1=TOT0*E1
N220 TOT2=TOT1/3600
N230 (DIS,TOT2)
