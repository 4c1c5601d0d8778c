; corpus-2.13.4.1-param-sub-example-1: copy of corpus part4/2.13.4.1-param-sub-
; example-1-main.nc (§2.13.4.1 example 1, figure 2.127, seed L9104-9116); the
; subroutine is lib/MP0/SUB500.nc. E30 = 62.5 hole radius, E31 = 25 connection
; radius, E25 = 160 feed; the temporary origin is origin 0 + (65,48).
; Expected (derived), from the temporary origin: line to (25,37.5) at F2000;
; G03 to (0,62.5) about (0,37.5), R25, 90 degrees, F160; a full circle R62.5
; about (0,0); G03 to (-25,37.5) about (0,37.5), R25, 90 degrees; line to
; (0,0) at F2000. Afterwards E35 = 37.5, E31 = -25 (changed by SUB500).
; Changed: the annotation after N136 is dropped; the manual's lines of dots are
; comments; N139 (DIS,E35,E31) and N140 M30 are added.
; Tools: profiles/flow-tools.toml (T12.12).
;...............
N128 (DIS,"..............")
N129 S330 T12.12 M6
N130 (UOT,0,X65,Y48)
N131 G X Y M3
N132 Z-30
N133 E30=62.5
N134 E31=25
N135 E25=160
N136 (CLS,SUB500)
N137 (UAO,0)
N138 G Z 20
N139 (DIS,E35,E31)
N140 M30
