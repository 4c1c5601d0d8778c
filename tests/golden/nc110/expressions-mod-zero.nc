; expressions-mod-zero: MOD(A,0) divides by zero (MOD(A,B) = A - B*INT(A/B), decision 10;
; NC4030), found by the dry run of ncc check at line 5.
E30=MOD(5,2)
; error here
E31=MOD(E30,E30-1)
