; corpus-2.10.3-rms-examples: copy of corpus/nc110/part3/2.10.3-rms-examples.nc (§2.10.3
; seed L5002-5025). Expect: RMS = 110 makes the G84 return 10 % faster, RMS = 10 90 %
; slower (the return itself: corpus-1.2.17-rms-tapping-return-speed.nc). Corrected: the
; parenthesised annotations "(+10% запрограммированного F)" are prose, not a code: dropped.
; Added: DIS after each.
RMS = 110
(DIS,RMS)
RMS = 10
(DIS,RMS)
