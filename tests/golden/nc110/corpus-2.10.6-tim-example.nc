; corpus-2.10.6-tim-example: copy of corpus/nc110/part3/2.10.6-tim-example.nc (§2.10.6 seed
; L5222-5240). Expect: N10 stores the system clock TIM0 into TIM1; N90 stores into TIM2
; the time from N10 to N90; (DIS,TIM2) shows it. Corrected: OCR GO = G0, TIMO = TIM0; the
; annotations after " - " dropped. The elided blocks ("......") are supplied: N9 G0 X0
; (no travel), N20 G1 X100 F600 (10 s, decision 50), N89 G0 X100 (no travel): TIM2 = 10.
N9 G0 X0
N10 # TIM1=TIM0
N20 G1 X100 F600
N89 G0 X100
N90 # TIM2=TIM0-TIM1
(DIS,TIM2)
