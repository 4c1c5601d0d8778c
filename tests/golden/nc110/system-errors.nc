; system-errors: what may stand in an assignment to a system variable (§2.10, Table 3.3;
; decision 16). Unknown names and keyboard-only codes (ORA, VOL) are NC3028; JOG and RAP
; are set from the keyboard, TIM0 (the clock) and RMNpq are read-only: NC3029. TMR UOV
; RMS UGF and the flags take a constant or one E parameter, not an expression: NC3030;
; TIM, TOT are numbered 0..6, RMN 11..59: NC3030; a flag takes 0 or 1: NC4048; a text: NC3032.
FOO=1
ORA=1
VOL=1
JOG=1
RAP=0
TIM0=5
RMN12=3
TMR=E30+1
UOV=2*E30
RMS=E5+1
UGF=-E28
USB=1-E1
TIM7=1
TIM=1
TOT7=0
E3=RMN61
USB=2
USO=0.5
TMR="A"
; expressions are allowed for TIM1..TIM6 and TOT0..TOT6 (§2.10.6-§2.10.7): no error
N10 # TIM1=TIM0
N90 # TIM2=TIM0-TIM1
TOT1=TOT0*E1
