; Spindle ranges and the part change (Table 2.3, seed L1773-1870; docs/trace.md
; spindle_range, part_change): M41-M44 force range 1-4 and M45 the automatic change at the
; start of the block; M40 cancels the forced range and M60 changes the part at the end.
; Expected: N1 spindle_range 1, rapid; N2 range 2, rapid; N3 range 3, rapid; N4 range 4,
; rapid; N5 rapid, spindle_range none; N6 spindle_range auto, rapid, part_change.
N1 G0 X10 M41
N2 X20 M42
N3 X30 M43
N4 X40 M44
N5 X50 M40
N6 X60 M45 M60
