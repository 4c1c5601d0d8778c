; corpus-2.4.4-block-numbers: copy of corpus/nc110/part1/2.4.4-block-numbers.nc (§2.4.4
; seed L1490-1497). Expect: three blocks numbered 125: plain; with the label INIZIO (a
; blank before 125); with the block-skip field and the label FINE. The manual gives three
; separate examples; here they share a file, so N125 repeats, which is allowed (decision
; 7). Changed: nothing. ncc check finds nothing; a run makes no event.
N125
"INIZIO" N 125
/"FINE" N 125
