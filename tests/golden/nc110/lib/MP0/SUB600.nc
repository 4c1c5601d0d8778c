; SUB600 on device MP0: the parametric subroutine of figure 2.128 (§2.13.4.1
; example 2, seed L9147-9158; corpus part4/2.13.4.1-param-sub-example-2-
; SUB600.nc), corrected: 'N602 E3=E3-1' (both renderings) reads E3=E1-1, as
; SUB700's N704 E5=E1-1; E3 is set nowhere else. The as-printed copy is
; lib/MP1/SUB600.nc.
; A row of E1 holes from (E30,E31), pitch E32, at the angle E25: N604 drills
; the first, the body N606 (G91 along the rotated X) the other E1-1.
N600 (UOT,0,XE30,YE31)
N601 (URT,E25)
N602 E3=E1-1
N603 GE2 RE34 ZE 35
N604 XY
N605 (RPT,E3)
N606 G91 XE32
N607 (ERP)
N608 G90
N609 G80
N610 (UAO,0)
N611 (URT,0)
