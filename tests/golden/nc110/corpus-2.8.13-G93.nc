; Corpus copy of part2/2.8.13-G93-example.nc (seed §2.8.13, L4542-4583): inverse-time
; feed; F is valid only in the block where it is programmed, so it is repeated in each.
; Supplied: the manual prints placeholders "X...Y...F..."; the copy uses X50 Y0 F2 and
; X50 Y40 F4.
; Derived (decision 50): under G93 a block takes 1/F minutes whatever its length: the
; first 0.5 min = 30 s, the second 0.25 min = 15 s; TIM0 45 s. A block without its own
; F is an error (NC4014, tested in motion-feed-errors).
G93 G1 X50 Y0 F2
   X50 Y40 F4
; added: the clock
E25 = TIM0
(DIS,E25)
