; corpus-2.10.9-mcd-example: copy of corpus/nc110/part3/2.10.9-mcd-example.nc (§2.10.9 seed
; L5307-5340). Expect: for a largest corner angle alpha = 180 degrees, MCD = 1 +
; sin(alpha - 90) = 1 + 1 = 2. Corrected: only the last line is program text; the first
; two are the manual's derivation ("[Sin(α – 900)]", 900 = 90 degrees) and are dropped
; (MCD takes a constant or one E parameter, not an expression: decision 16). Added: the
; derivation computed into E30 (1 + SIN(180-90) = 2) and set through it; DIS after each.
MCD = 2
(DIS,MCD)
MCD = 0
E30 = 1 + SIN(180-90)
MCD = E30
(DIS,MCD)
