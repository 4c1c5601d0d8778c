; SUB700 on device MP0: the parametric subroutine of figure 2.129 (§2.13.4.1
; example 3, seed L9202-9217; corpus part4/2.13.4.1-param-sub-example-3-
; SUB700.nc), copied unchanged. A grid of E2 rows of E1 holes: the pitch E31
; along the angle E25, the rows E32 apart along the angle E26, serpentine (the
; row step changes sign after each row). It drills with the caller's G81; N706
; moves G91 by (E41,E42), zero in the first pass, and still drills (decision 52).
N700 E33=E31*COS(E25)
N701 E34=E31*SIN(E25)
N702 E41=0
N703 E42=0
N704 E5=E1-1
N705 (RPT,E2)
N706 G91 XE41 YE42
N707 (RPT,E5)
N708 XE33 YE34
N709 (ERP)
N710 E41=E32*COS(E26)
N711 E42=E32*SIN(E26)
N712 E33=NEG(E33)
N713 E34=NEG(E34)
N714 (ERP)
N715 G80 G90
