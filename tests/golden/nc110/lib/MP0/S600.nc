; S600 on device MP0: the subroutine of figure 2.119 (§2.13.2.2, seed L8493-8498;
; corpus part4/2.13.2.2-CLS-example-3-S600.nc). N501 only sets the G81 cycle;
; N502-N505 drill at X0Y0, X0Y-15, X30Y-15, X30Y0 of the caller's origin; N506
; cancels the cycle; the end of the file returns.
; Changed: the manual elides the levels (G81R..Z..); R2 and Z-10 are supplied.
N501 G81R2Z-10
N502 XY
N503 Y-15
N504 X30
N505 Y
N506 G80
