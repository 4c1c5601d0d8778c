; expressions-tan-90: TAN is undefined at odd multiples of 90 degrees (§2.12; decision 10;
; NC4031), at line 6: the value -270 and TAN are named. TAN(89.99) and TAN(180) are fine.
E30=TAN(89.99)
E31=TAN(180)
; error here
E32=TAN(-270)
