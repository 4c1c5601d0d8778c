; Corpus copy of part2/2.8.3-indexing-table-example.nc (seed §2.8.3, L2862-2898), run
; with profile motion-indexing: P an indexing table of 5 degrees per index at 3600 deg/min.
; Changed: the dotted elisions between the blocks are dropped; the clock blocks and N50
; are added.
; The manual: P's value is a number of indexes; N24 absolute to index 10; N41 incremental
; +2 indexes (12); "G90 P0" back to index 0.
; Expected (decision 48): the trace counts indexes: P10, P12, P0. Clock: 50 deg = 0.8333333
; s; then 10 deg (1/6 s) and 60 deg (1 s). N50: the table turns first (P3, 15 deg, 0.25 s),
; then X moves (10/10000 min = 0.06 s), two rapid events: TIM0 2.31 s.
N24 P10
E25 = TIM0
(DIS,E25)
N41 G91 P2
G90 P0
; added: an index and a linear axis in one block
N50 X10 P3
E25 = TIM0
(DIS,E25)
