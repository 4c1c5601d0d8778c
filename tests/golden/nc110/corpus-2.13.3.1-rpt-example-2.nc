; corpus-2.13.3.1-rpt-example-2: copy of corpus part4/2.13.3.1-RPT-example-2.nc
; (§2.13.3.1, figure 2.121 "8 holes, pitch 10", seed L8663-8674).
; Expected (derived): 16 G81 holes, R5 Z-10: Y10 at X10, 20, ..., 80 (N3, then
; the body N5 7 times: (RPT,7) runs it 7 times in total, decision 20), then Y50
; at X80, 70, ..., 10 (N7 Y40 is incremental: G91 is still in force; then N9 7
; times). R and Z stay absolute levels under G91 (decision 51). Each hole: rapid
; over the hole, rapid to R (Z5), feed to Z-10, rapid back to Z5.
; Copied unchanged. Tools: profiles/flow-tools.toml (T1.1).
(DIS," отверстия ")
N1  F200 S900 T1.1 M6
N2  G81 R5 Z-10 M3
N3  X10 Y10
N4  (RPT,7)
N5  G91 X10
N6  (ERP)
N7  Y40
N8  (RPT,7)
N9  X-10
N10 (ERP)
N11 G80 G90 M5
