; expressions-gtl-line: FEL(5,1), the sine of line l5's angle (§2.12 seed L7693-7698):
; l5 is undefined until GTL exists (decision 10, NC4050), reported by ncc check at line 3.
E30=FEL(5,1)
