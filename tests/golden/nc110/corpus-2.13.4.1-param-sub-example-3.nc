; corpus-2.13.4.1-param-sub-example-3: copy of corpus part4/2.13.4.1-param-sub-
; example-3-main.nc (§2.13.4.1 example 3, figure 2.129, seed L9202-9213); the
; subroutine is lib/MP0/SUB700.nc. E25 row angle 30, E26 column angle 80, E31
; pitch in a row 15, E32 pitch between rows 12, E1 = 8 holes a row, E2 = 5 rows;
; start X20 Y25; the caller sets G81 R3 Z-20 and SUB700 drills with it (modal
; state shared, decision 21).
; Expected (derived): 5 rows x 8 = 40 holes, serpentine: row 1 from (20,25) to
; (110.933,77.5), row 2 from (113.016,89.318) back to (22.084,36.818), ...,
; the last at (119.268,124.771); the first hole needs N706's zero-length G91
; move (decision 52). At the end E5=7, E33=-12.99038106, E34=-7.5,
; E41=2.083778132, E42=11.81769304 (LR, 10 digits); G80 G90 in force.
; Added: N103 (DIS,...) of those parameters, N104 a G90 move (X0 Y0) and M30.
; Tools: profiles/flow-tools.toml (T2.2).
N20  (DIS,".............")
N30  F9000 S3000 T2.2 M6
N40  G X20 Y25 M3
N50  G81 R3 Z-20
N60  E25=30
N70  E26=80
N80  E31=15
N90  E32=12
N100 E1=8
N101 E2=5
N102 (CLS,SUB700)
N103 (DIS,E5,E33,E34,E41,E42)
N104 G X Y M30
