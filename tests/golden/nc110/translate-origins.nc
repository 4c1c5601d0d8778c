; translate-origins: NC-110's (UAO,n) as ISO's work offset (G54 for origin 1)
; where origin n declares every axis the target machine has (profile
; frame-origins: origin 1 declares X Y Z B). The program selects its origin
; before it moves, so ISO's G54 at power-on does not matter.
(UAO,1)
G0 X10 Y10 Z5
G1 X20 F100
M30
