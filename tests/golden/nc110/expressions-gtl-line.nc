; expressions-gtl-line: FEL(5,1), the sine of line l5's angle (§2.12 seed L7693-7698):
; no block defines l5 (decision 71, NC4050), reported by ncc check at line 3.
E30=FEL(5,1)
