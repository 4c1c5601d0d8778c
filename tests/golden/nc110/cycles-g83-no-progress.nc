; NC-110 §2.8.9.2, decision 53 (NC4069) in a run: G83 I5 K.5 from R2: the pecks 5, 2.5
; and 1.25 would reach -3, -4.5, -4.75, then the next peck 0.625 is not deeper than the
; 1 mm the tool comes back: the hole would never end. It is refused before the tool
; moves (as a hole of too many pecks, cycles-g83-too-many-pecks), and the run stops.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
F100 S500 M3
G83 R2 Z-25 I5 K.5
X20
G80
