; Corpus copy of part2/2.8.1.2-G01-fig2.2-example.nc (seed §2.8.1.2, L2099-2100, Fig. 2.2).
; Unchanged except this header; the last two blocks are added to show the run's clock.
; The manual: N80 moves the tool on a straight line from X10 Y10 to X90 Y40 at F200.
; Start: all axes at 0 of origin 0 (nc110-corpus.md §0.4); power-on G00, G94 (decision 38).
; Derived: N79 is a rapid (modal G00) of max(10,10)/10000 min = 0.06 s; N80 is 85.44004 mm
; at 200 mm/min = 25.63201 s; TIM0 (decision 50) then reads 25.69201 s.
N79 X10 Y10
N80 G01 X90 Y40 F200
; added: the clock after the two moves, as an RE parameter (7 significant digits)
E25 = TIM0
(DIS,E25)
