; corpus-2.10.2-uov-examples: copy of corpus/nc110/part3/2.10.2-uov-examples.nc (§2.10.2
; seed L4970-4999). Expect: UOV = 0.5 an allowance of 0.5; E30 = 1.5 then UOV = E30 one of
; 1.5; UOV=0 cancels. Corrected: annotations dropped; Cyrillic Е in E30 made Latin. Added:
; DIS after each, and UOV=0.
UOV = 0.5
(DIS,UOV)
E30 = 1.5
UOV = E30
(DIS,UOV)
UOV=0
(DIS,UOV)
