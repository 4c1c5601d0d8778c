; system-timers: TIM0 reads the run's clock (§2.10.6 seed L5209-5240; decision 50): feed
; moves at F, dwells; TIM1..TIM6 and TOT0..TOT6 store times and take expressions
; (§2.10.7 L5243-5282; decision 16); RMNpq reads 0 (§2.10.10; decision 16).
; The manual's example of §2.10.6 and §2.10.7 with the elided blocks supplied:
; 100 mm at F600 = 10 s, then a dwell of 2 s: TIM2 = 12 s.
N10 # TIM1=TIM0
(DIS,TIM1)
G1 X100 F600
TMR=2
G4
N90 # TIM2=TIM0-TIM1
(DIS,TIM2)
; batch time of 75 parts: 12 * 75 = 900 s = 0.25 h
E1=75
N200 # TOT0=TIM0-TIM1
N210 TOT1=TOT0*E1
N220 TOT2=TOT1/3600
(DIS,TOT1)
N230 (DIS,TOT2)
; the remaining path of axis 2 of process 1 (L5356): 0 / 20 = 0
E25=RMN12/20
(DIS,E25)
(DIS,RMN11)
