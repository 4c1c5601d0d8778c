; Corpus copy of part2/2.8.1.4-G02-R-plus-fig2.6-example.nc (seed §2.8.1.4, L2437-2445,
; Fig. 2.6 path 1, labels L13971-13979). R+ selects the arc of at most 180 degrees
; (decision 39). Unchanged except this header and the clock blocks.
; Start X0 Y0 (the figure). Expected: clockwise about X20 Y0, radius 20, 90 degrees;
; 31.4159 mm at F100 = 18.84956 s.
G02 X20 Y20 R+20 F100
; added: the clock
E25 = TIM0
(DIS,E25)
