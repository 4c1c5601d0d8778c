; memory-overflow-bit: a bit (BL) holds 0 or 1 (Table 2.7 seed L5120; decision 17):
; SA1=2 does not fit (NC4032, line 5), found by the dry run of ncc check.
SA0=1
SA1=0
SA1=2
