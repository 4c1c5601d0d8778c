; NC-110 §2.8.9.1 example 1, Fig. 2.26 (seed lines 3764-3772; no corpus file): G81
; drilling at four points. The leading "....." line of the manual is left out and the
; annotations are moved here: N33 "sets the parameters of the drilling cycle",
; N34-N37 "move to point 1 (2, 3, 4) and run the cycle", N38 "cancels the cycle".
; Checks (decisions 51, 52): N33 stores G81 with R3 Z-15 and moves nothing (M3 starts
; the spindle); each of N34-N37 is one hole: rapid in XY at the tool's height (Z100
; from the profile for the first, then R 3), rapid to R3 when not there, feed F95 to
; Z-15, rapid to R3; holes at (15,15) (15,60) (80,60) (80,15); N38 cancels, then
; moves to Z50 in the modal G00, M5 at the end.
N32 S1100 F95 T3.3 M6
N33 G81 R3 Z-15 M3
N34 X15 Y15
N35 Y60
N36 X80
N37 Y15
N38 G80 Z50 M5
