; parameters-overflow: a value outside the class of the E parameter it is stored into is
; an error, not a wrap (Table 2.8 seed L7641-7654; decision 8, NC4032); a constant right
; side is reported by ncc check, at the value. Rounding comes first: -0.5 -> -1.
E7=300
E7=-1
E7=-0.5
E7=255.5
E10=40000
E10=-32768.5
E20=2147483648
E20=-2147483648
E31=10000000000000
E30=-10000000000000
E25=350000000000000000000000000000000000000
; in range: no error
E7=255.4
E10=-32768.4
E25=340000000000000000000000000000000000000
E31=9999999999999
