; expressions-arc-domain: ARC (arc cosine) of a value outside [-1, 1] is a run-time error
; (§2.12; decision 10; NC4031) at line 5: the value -1.0001 and ARC are named.
E30=ARC(-1)
; error here
E31=ARC(-1.0001)
