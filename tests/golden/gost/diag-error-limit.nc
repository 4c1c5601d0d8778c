diag-error-limit: eight errors, of which --error-limit 3 shows three and then NC1019
%
N1 L1 (NC2001)
N2 L2 (NC2001)
N3 L3 (NC2001)
N4 L4 (NC2001)
N5 L5 (NC2001)
N6 L6 (NC2001)
N7 L7 (NC2001)
N8 L8 (NC2001)
N9 M30
