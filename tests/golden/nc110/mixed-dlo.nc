; DLO (NC-110 §2.13.5.3, seed lines 9431-9470; §1.2.39-§1.2.40); decision 34: limits
; taken from the current origin, stored in machine coordinates, in either order; a limit
; beyond the machine's travel is the machine's; every move is checked before it starts;
; limits are not scaled (decision 28).
; Profile frame-limits: origin 1 = X100 Y50; machine travel X -500..500, Y -400..400.
; Checks:
; - (DLO,X100 X-50) from origin 1: X -50..100 (machine 50..200), upper limit first;
; - (DLO,Y-1000 Y1000): beyond the travel, so machine -400..400, i.e. Y -450..350 from
;   origin 1; moves to the four limits are allowed;
; - after (UAO,0) the limits stay where they are on the machine: G0 X50 and G0 X200
;   are the limits;
; - with (SCF,2,X), G0 X100 goes to X200 (the limit, not scaled): allowed; G0 X101
;   would reach X202: NC4059 before the move, the limits shown from the current origin.
(UAO,1)
G0 X0 Y0
(DLO,X100 X-50)
(DLO,Y-1000 Y1000)
G0 X100 Y-450
G0 X-50 Y350
(UAO,0)
G0 X50
G0 X200
(SCF,2,X)
G0 X100
G0 X101
