; expressions-gtl-field: the second argument of FEP is the field, 1 (abscissa) or 2
; (ordinate) (§2.12 seed L7700-7703): FEP(1,3) is a domain error (NC4031) naming 3 and
; FEP, at line 4.
E30=FEP(1,3)
