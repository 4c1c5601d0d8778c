; system-timers-digits: TIM and TOT hold reals of class RE (§2.10.6-§2.10.7: a constant,
; an RE parameter E25-E29 or an expression); DIS shows an RE value with 7 significant
; digits (decision 37), as it does for E25: all three messages read 0.3333333.
E25=1/3
(DIS,E25)
TIM3=1/3
(DIS,TIM3)
TOT4=1/3
(DIS,TOT4)
