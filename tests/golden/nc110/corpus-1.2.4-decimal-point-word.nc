; corpus-1.2.4-decimal-point-word: copy of corpus/nc110/part1/1.2.4-decimal-point-word.nc
; (§1.2.4 seed L358-363). Expect: one axis word, X target -20.275 in the active unit
; (mm under G71, the power-on unit), numbers written as read with the decimal point, no
; implied decimal; the motion is the power-on G00: rapid to X-20.275.
; Changed: nothing (the manual's sentence punctuation " ." was already dropped).
X-20.275
