; corpus-2.10.11-ugf-examples: copy of corpus/nc110/part3/2.10.11-ugf-examples.nc (§2.10.11
; seed L5370-5398). Expect: UGF = 20.5 sets the skew-axes angle to 20.5 degrees; E26=75
; then UGF=E26 (class RE) to 75. Changed: DIS added after each.
UGF = 20.5
(DIS,UGF)
E26=75
UGF=E26
(DIS,UGF)
