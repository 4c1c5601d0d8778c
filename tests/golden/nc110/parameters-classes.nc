; parameters-classes: E parameter classes (Table 2.8 seed L7641-7654; §2.12 L7710-7711
; "converted, if compatible"; decision 8). BY E0-E9 0..255, IN E10-E19 -32768..32767,
; LI E20-E24 +-2147483647: stores round half away from zero. RE E25-E29 an IEEE float
; (shown with 7 digits), LR E30- a double (10 digits) below 1e13. All start at 0.
; (DIS shows BY IN LI as integers, RE with 7, LR with 10 significant digits, decision 37)
; at the start every parameter is 0
(DIS,E9)
(DIS,E40)
; 0.3*10 is 2.9999999999999996 in doubles: rounds to 3
E1=0.3*10
(DIS,E1)
; halves away from zero: 2.5 -> 3, 254.5 -> 255, -2.5 -> -3, -0.4 -> 0
E2=2.5
(DIS,E2)
E3=254.5
(DIS,E3)
E10=-2.5
(DIS,E10)
E4=-0.4
(DIS,E4)
; the class limits are kept
E11=-32768
(DIS,E11)
E12=32767.4
(DIS,E12)
E20=-2147483647
(DIS,E20)
E21=2147483647
(DIS,E21)
; RE: 0.1 as a float; 123456789 becomes 123456792
E25=0.1
(DIS,E25)
E26=123456789
(DIS,E26)
; reading an RE into an LR shows the float: 0.1f*10 = 1.0000000149...
E35=E25*10
(DIS,E35)
E36=E26
(DIS,E36)
; and into an IN it rounds: 1
E13=E25*10
(DIS,E13)
; LR: 1/3 with 10 digits; the largest value below 1e13
E30=1/3
(DIS,E30)
E31=9999999999999.9
E32=E31-9999999999999
(DIS,E32)
