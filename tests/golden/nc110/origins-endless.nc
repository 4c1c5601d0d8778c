; An endless rotary axis in a transformed frame (NC-110 §2.8.4, §2.13.1.4); decisions 27,
; 29 and 48: the sign of an endless axis' target gives the way it turns; a mirror on X
; (or any transform of other axes) does not change how B turns.
; Profile frame-endless: B rotary, endless.
; Checks: G0 B-90 turns the negative way to 90 (B-270 from 0); with (MIR,X), the same
; block from B0 (after G0 B0, the short way) must give the same turn, not a move to -90.
; The clock shows the way: 270 + 90 + 270 = 630 degrees at 10000 deg/min: TIM0 3.78 s.
G0 B-90
G0 B0
(MIR,X)
G0 B-90
E25=TIM0
(DIS,E25)
