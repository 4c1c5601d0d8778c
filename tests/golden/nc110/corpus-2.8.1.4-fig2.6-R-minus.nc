; Corpus copy of part2/2.8.1.4-G02-R-minus-fig2.6-example.nc (seed §2.8.1.4, L2437-2445,
; Fig. 2.6 path 2). R- selects the arc from 180 to 359.999 degrees (decision 39).
; Unchanged except this header and the clock blocks.
; Start X0 Y0 (the figure). Expected: clockwise about X0 Y20, radius 20, 270 degrees;
; 94.2478 mm at F100 = 56.54867 s.
G02 X20 Y20 R-20 F100
; added: the clock
E25 = TIM0
(DIS,E25)
