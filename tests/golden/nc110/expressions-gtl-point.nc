; expressions-gtl-point: FEP(4,2), the ordinate of point p4 (§2.12 seed L7700-7703), is
; not defined by any block (decision 71, NC4050), reported by ncc check at line 3.
E34=FEP(4,2)
