; translate-origins-zero: NC-110's origin 0 (no origin) is ISO's G54 where the target
; machine's offset 1 is zero, as the start takes it; its temporary and incremental
; shifts are G52. Expected: X10 Y10 Z5; after (UOT,0,X10,Y-20) X20 Y-10; after the
; UIO shifts X5 and Y5 (X15 Y-15) the feed to X10 ends at X25, Y stays; (UAO,0): X10 Y10
G0 X10 Y10 Z5
(UOT,0,X10,Y-20)
G0 X10 Y10
(UIO,X5)
(UIO,Y5)
G1 X10 F100
(UAO,0)
G0 X10 Y10
M30
