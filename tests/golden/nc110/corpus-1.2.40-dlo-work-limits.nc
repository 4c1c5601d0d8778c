; Copy of corpus part1/1.2.40-dlo-work-limits.nc (NC-110 §1.2.40, seed lines 1045-1046;
; the rule is §2.13.5.3, lines 9431-9470, and §1.2.39). Added: moves N22-N24.
; Checks (decision 34): the limits are taken from the current origin (origin 0): X from
; -50 to 100, Z from -60 to 20; a move to the limits themselves is allowed (N22, N23);
; N24 G0 X101 would leave the field: NC4059 before the move starts (no rapid event).
N20 (DLO,X-50 X100)
N21 (DLO,Z-60 Z20)
N22 G0 X100 Z20
N23 G0 X-50 Z-60
N24 G0 X101
