; NC-110 §2.8.9.1 example 2, Fig. 2.27 (seed lines 3780-3786; no corpus file): G81 with
; one R and the feed in the cycle's block, one hole at X0 in the current Y.
; Changed: N31 prints (DIS,"TWIST DRILL D=6.5) with a typographic opening quote and no
; closing one; plain quotes here. N30 is added to put the tool at X40 Y25 Z100 so that
; "X0" visibly keeps Y25. N36 "G.. X.. Z.." is an elision, left out.
; Checks: N33 stores G81 R5 Z-70 and F45 (feed_rate event, no motion); N34 drills one
; hole at (0,25): rapid XY at Z100, rapid to Z5, feed to Z-70, rapid to Z5; N35
; cancels and moves nothing.
N30 G X40 Y25 Z100
N31 (DIS,"TWIST DRILL D=6.5")
N32 G97 S1000 T4.4 M06 M3 M7
N33 G81R5 Z-70 F45
N34 X0
N35 G80
