; dly-dwell: (DLY,t) dwells t seconds, 0..32, a constant or one LR parameter
; (E30 on), whatever the feed mode (§2.13.6.2 L9617-9639; codes digest §4).
; '#' (synchronisation, "DLY needs #") is accepted and changes nothing
; (decision 18). Each dwell is a 'dwell' event in seconds.
(DLY,2)
E48=2
(DLY,E48)
(DLY,0)
(DLY,32)
(DLY,0.5)
E30=32
(DLY,E30)
# (DLY,1.25)
; under G95 (feed per revolution) DLY is still in seconds
G95
(DLY,1)
; TIM0, the run's clock, counts the dwells: 2+2+0+32+0.5+32+1.25+1 = 70.75 s
(DIS,TIM0)
M30
