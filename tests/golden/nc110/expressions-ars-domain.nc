; expressions-ars-domain: ARS (arc sine) of a value outside [-1, 1] is a run-time error
; (§2.12; decision 10; NC4031) at line 5: the value 1.5 and ARS are named.
E30=ARS(1)
; error here
E31=ARS(E30/60)
