; SUB600 on device MP1: the subroutine of figure 2.128 (§2.13.4.1 example 2,
; seed L9147-9158; corpus part4/2.13.4.1-param-sub-example-2-SUB600.nc) as
; printed: 'N602 E3=E3-1' with E3 = 0 stores -1 into a BY parameter, a run-time
; error at N602 (decision 8). The corrected copy is lib/MP0/SUB600.nc.
N600 (UOT,0,XE30,YE31)
N601 (URT,E25)
N602 E3=E3-1
N603 GE2 RE34 ZE 35
N604 XY
N605 (RPT,E3)
N606 G91 XE32
N607 (ERP)
N608 G90
N609 G80
N610 (UAO,0)
N611 (URT,0)
