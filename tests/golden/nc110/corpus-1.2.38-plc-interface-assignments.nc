; corpus-1.2.38-plc-interface-assignments: copy of corpus/nc110/part1/
; 1.2.38-plc-interface-assignments.nc (§1.2.38 seed L1002-1012; §2.10.4). Expect:
; SA12=SK.BL: bit 12 of packet A := the first bit of packet K; SK5=SK7: byte 5 of K :=
; byte 7 of K; SA128=1: bit 128 of A set; SK7.3CH="RIF": R I F from byte 7 of K;
; SA3.BY=255: byte 3 of A := 255. SA counts bits, SK bytes (decision 17); SK.BL has no
; index: 0. Changed: the memories start at 0, so two blocks first give the copied values
; something to copy (SK byte 0 = 1, so its bit 0 is 1; SK7 = 9); DIS blocks after.
SK0=1
SK7=9
SA12=SK.BL
SK5=SK7
SA128=1
SK7.3CH="RIF"
SA3.BY=255
; bit 12 = bit 4 of byte 1: SA12 = 1, SA1.BY = 16
(DIS,SA12)
(DIS,SA1.BY)
; SK5 got 9 before RIF overwrote SK7
(DIS,SK5)
; bit 128 = bit 0 of byte 16
(DIS,SA16.BY)
; R I F = 82 73 70
(DIS,SK7.3CH)
(DIS,SK7)
(DIS,SK9)
; byte 3 = bits 24..31 all set, bit 32 not
(DIS,SA3.BY)
(DIS,SA24)
(DIS,SA31)
(DIS,SA32)
