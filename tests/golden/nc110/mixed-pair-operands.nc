; A pair operand of DLO and DSA names one axis twice (NC-110 §2.13.5.3: "a pair of words
; of type axis-size with the same axis name"; §2.13.5.5); decision 19.
; Checks (ncc check): X-1 Y1 in DLO and X0 Y1 in DSA mix two axes: NC3018 at the pair,
; saying that both values must belong to one axis.
(DLO,X-1 Y1)
(DSA,1,X0 Y1,Y0 Y1)
