; gtl-plane-dpi: GTL in another plane (end of §2.11.9.3, corpus part3/
; 2.11.9.3-plane-dpi-example.nc): (DPI,B,X) first, then the elements with the plane's
; letters, B the abscissa and X the ordinate; I J stay the centre's. The numbers are
; example 1's, so p1 = B13.646 X72.536 (gtl-example-1-nominal); FEP shows it. Writing
; the letters the other way round (X then B) gives the same point; Y is not an axis of
; the plane (NC4100 at N8, the run stops there).
N1 (DPI, B, X)
N2 l1= B70 X40, a150
N3 l2= B8 X8, a-95
N4 p1= l1, l2
N5 p2= X72.536 B13.646
N6 E30=FEP(1,1)
E31=FEP(1,2)
E32=FEP(2,1)
E33=FEP(2,2)
(DIS,E30," ",E31," ",E32," ",E33)
N7 c1= I70 J40, r-25
N8 p3= X1 Y2
