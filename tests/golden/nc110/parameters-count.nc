; parameters-count: how many E parameters exist is set at configuration (Table 2.8 seed
; L7635, L7654; profile nc110.e_count, default 1000 = E0..E999): with
; profiles/lang-e-count.toml (50) E50 does not exist (NC2017, lines 6 and 7).
E49=1
E30=E49+1
E50=1
G0 XE50
