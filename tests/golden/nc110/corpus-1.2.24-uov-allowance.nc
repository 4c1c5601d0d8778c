; corpus-1.2.24-uov-allowance: copy of corpus/nc110/part1/1.2.24-uov-allowance.nc (§1.2.24
; seed L677; §2.10.2 L4970-4999). Expect: the allowance UOV = 1.5 (it acts only under
; cutter radius compensation, not supported yet); UOV=0 cancels it. Changed: DIS blocks
; and UOV=0 are added to show the values 1.5 and 0.
UOV=1.5
(DIS,UOV)
UOV=0
(DIS,UOV)
