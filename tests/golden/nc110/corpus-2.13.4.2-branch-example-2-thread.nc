; corpus-2.13.4.2-branch-example-2-thread: copy of corpus part4/2.13.4.2-branch-
; example-2-thread.nc (§2.13.4.2 example 2, figure 2.131, M60x3, seed
; L9331-9353): a thread cut in passes with the diametral U axis of a boring head
; (profiles/flow-thread.toml: U diameter, spindle encoder).
; Parameters: E30 first-pass diameter 56.8, E31 infeed 0.5 on the diameter, E32
; return diameter 50, E33 final diameter 60.
; Expected (derived): G33 Z-45 K3 passes at U 56.8, 57.3, 57.8, 58.3, 58.8,
; 59.3, 59.8 (the loop "I": BGT E30 > E33 jumps forward to "F" when E30 = 60.3,
; BNC jumps back to "I" otherwise), then the final pass at U60: 8 passes, each
; a thread of pitch 3 from Z5 to Z-45, with a retract to U50 and Z5 between
; them. At the end E30 = 60.3. Labels "I" and "F" are letters that are also
; addresses (decision 3).
; Added: N23 (DIS,E30) and N24 M30 for the elided end.
N1  (DIS,"..............")
N2  S150 T5.5 M6
N3  G X66 Y98 Z5 M3
N4  E30=56.8
N5  E31=0.5
N6  E32=50
N7  E33=60
"I" N8
N9  G Z5
N10 UE30
N11 G33 Z-45 K3
N12 GUE32
N13 E30=E30+E31
N14 (BGT,E30,E33,F)
N15 (BNC,I)
"F" N16
N17 GUE32
N18 Z5
N19 UE33
N20 G33 Z-45 K3
N21 GUE32
N22 Z20
;..................
N23 (DIS,E30)
N24 M30
