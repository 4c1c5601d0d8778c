; A machine profile adds an M code (nc110.tables.m_codes, docs/profile.md; §2.7.8: the
; machine logic may add M codes). Profile mcodes-machine: M20 = coolant.mist, set mist.
; Expected (ncc check): N2 NC3005 at M20 (M09 and M20 control the mist coolant); N3 M15
; is still not defined (NC3004); N1 M20 is correct.
N1 G0 X10 M20
N2 M09 M20
N3 M15
M30
