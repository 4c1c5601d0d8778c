; Corpus copy of part2/2.8.4-extended-rotary-example3.nc (seed §2.8.4, L2904-2958,
; Fig. 2.12), run with profile motion-endless: B an extended-range (endless) rotary axis
; at 3600 deg/min, at 0 degrees at the start. The clock blocks are added.
; The manual: B turns two full turns plus 45 degrees (765 degrees in all) and the screen
; shows B45 (the position "always stays in the range 0 to 359.9999", L2907).
; Expected (decision 48): a rapid to B45 (shown in 0..359.9999); the clock 765 deg at
; 3600 deg/min = 12.75 s.
G91 B765
; added: the clock
E25 = TIM0
(DIS,E25)
