; translate-origins-partial: origin 2 of profile frame-origins declares X and Y
; only: (UAO,2) keeps Z in origin 1 in NC-110, ISO's G55 would not. Refused.
(UAO,1)
G0 X10 Y10 Z5
(UAO,2)
G0 X10 Y10
M30
