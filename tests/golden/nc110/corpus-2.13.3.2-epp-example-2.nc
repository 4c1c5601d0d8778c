; corpus-2.13.3.2-epp-example-2: EPP example 2 of §2.13.3.2 (figure 2.124, seed
; L8902-8927; listed in the corpus digest as missing from part4), built from
; the seed lines: point-to-point drilling with three tools.
; Expected (derived): T1.1, G81 R3 Z-4, drills 8 holes in sequence: (100,100)
; (-100,100) (-100,-100) (100,-100) (40,40) (-40,40) (-40,-40) (40,-40);
; T2.2, G81 R3 Z-22, (EPP,D6,D10) runs N4-N9 (the label blocks included,
; both empty): the four +-100 holes again; T3.3, G81 R3 Z-24, (EPP,D10,END)
; runs N9-N14: the four +-40 holes again (decision 22).
; Changed: the manual's dots in the DIS texts are kept; the elided N26 reads
; G Z50 M30. Tools: profiles/flow-tools.toml.
N1  (DIS,"....................")
N2  F300 S2000 T1.1 M6 M3
N3  G81 R3 Z-4
"D6" N4
N5  X100 Y100
N6  X-100
N7  Y-100
N8  X100
"D10" N9
N10 X40 Y40
N11 X-40
N12 Y-40
N13 X40
"END" N14
N15 G80
N16 (DIS,"....................")
N17 F200 S1800 T2.2 M6 M3
N18 G81 R3 Z-22
N19 (EPP,D6,D10)
N20 G80
N21 (DIS,"....................")
N22 F220 S1600 T3.3 M6 M3
N23 G81 R3 Z-24
N24 (EPP,D10,END)
N25 G80
N26 G Z50 M30
