; SUB800 on device MP0: the parametric subroutine of figure 2.126 (§2.13.4, seed
; L9042-9053; corpus part4/2.13.4-CLS-circular-grid-SUB800.nc), copied
; unchanged. E1 holes, cycle G E2 with R E36 and Z E37, on radius E32 about
; (E30,E31) from the angle E33 in steps of E34. Each pass rotates the plane by
; E25 about the temporary origin (URT, decision 28), sets the cycle (N804 moves
; nothing, decision 51), drills at X=E32 Y0 (N805) and cancels the cycle (N807).
; It ends with origin 0 and no rotation.
N799 (DIS," круговые решения ")
N800 (UOT,0,XE30,YE31)
N801 E25=E33
N802 (RPT,E1)
N803 (URT,E25)
N804 GE2 RE36 ZE37
N805 XE32 Y
N806 E25=E25+E34
N807 G80
N808 (ERP)
N809 (UAO,0)
N810 (URT,0)
