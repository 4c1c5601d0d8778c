; expressions-manual-examples: the examples of §2.12 (seed L7724-7742; corpus/nc110/part3/
; 2.12-parameter-expression-examples.nc). Expect: N1 E37 = (E31*SIN(E30)+123.4567)/SQR(16);
; "LAB1" E51 = -0.00000124+5; E40 = tan 35 degrees; /E35 = the abscissa of point p37;
; E31 = -E31; E7 = 81; E25 = E25+30; E2 = byte 396 of packet K; E8 = SYVAR1.
; Corrected: the annotations after " - " and their wrapped lines dropped; Cyrillic Е in
; Е7, Е25, Е2 made Latin. Added: USB=0 first, so the '/' block with FEP (GTL, not
; supported yet: expressions-gtl.nc) is skipped; E31 = 2.5, SK396 = 44 and SYVAR1 = 9
; first, so the reads have values; DIS after. With E30 = 0: E37 = 123.4567/4 = 30.864175.
USB=0
E31=2.5
SK396=44
SYVAR1=9
N1 E37=(E31*SIN(E30)+123.4567)/SQR(16)
"LAB1"E51=-0.00000124+5
E40=TAN(35)
/E35=FEP(37,1)
E31=NEG(E31)
E7=81
E25=E25+30
E2=SK396
E8=SYVAR1
(DIS,E37)
(DIS,E51)
(DIS,E40)
(DIS,E35)
(DIS,E31)
(DIS,E7)
(DIS,E25)
(DIS,E2)
(DIS,E8)
