; corpus-2.10.4-sa-sk-examples: copy of corpus/nc110/part3/2.10.4-sa-sk-examples.nc
; (§2.10.4 seed L5057-5078). Expect: SA12=SK800.BL copies bit 800 of packet K into bit 12
; of packet A; SK5=SK7 byte 7 of K into byte 5; SA128 = 1 sets bit 128 of A;
; SK7.3CH="RIF" writes R I F from byte 7 of K; SA3.BY=255 writes 255 into byte 3 of A.
; Corrected: the list numbers "1)".."5)" and the Russian annotations after " - " with
; their wrapped lines are dropped. Added: SK100=1 (bit 800 = bit 0 of byte 100) and SK7=9
; first, so the copies have something to copy (memories start at 0); DIS after.
SK100=1
SK7=9
SA12=SK800.BL
SK5=SK7
SA128 = 1
SK7.3CH="RIF"
SA3.BY=255
(DIS,SA12)
(DIS,SK5)
(DIS,SA128)
(DIS,SK7.3CH)
(DIS,SA3.BY)
(DIS,SA25)
