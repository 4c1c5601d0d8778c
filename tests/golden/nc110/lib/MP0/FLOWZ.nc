; FLOWZ (cls-m30): a rapid move, then M30, which ends the whole run.
G X20
M30
(DIS,"NOT REACHED IN FLOWZ")
