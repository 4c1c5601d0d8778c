; SUB500 on device MP0: the parametric subroutine of figure 2.127 (§2.13.4.1
; example 1, seed L9120-9126; corpus part4/2.13.4.1-param-sub-example-1-
; SUB500.nc). E30 hole radius, E31 connection radius, E25 working feed.
; Path from the caller's origin: line to (E31, E30-E31); G03 to (0,E30) about
; (0,E35); full circle about (0,0); G03 to (-E31,E35) about (0,E35); line to
; (0,0). I and J are the absolute centre (decision 39).
; Not supported yet: cutter compensation. Removed: G41 (N501) and G40 (N505).
N500 E35=E30-E31
N501 G1 X E31 YE35 F2000
N502 G3 X YE30 I JE35 FE25
N503 I J
N504 E31=NEG(E31)
N505 XE31 YE35 I JE35
N506 G1 X Y F2000
