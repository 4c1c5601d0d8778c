; M conflict sets (NC3005): two M codes that control the same function must not share a block.
; Rule: ncc reads Table 2.3 (seed lines 1773-1833: M codes and the codes each one cancels) as the
; sets of stdlib/dialects/nc110/m_codes.tsv: stop {M00 M01 M02 M30}, spindle {M03 M04 M05 M13 M14
; M19}, mist {M07 M09}, flood {M08 M09}, clamping {M10 M11}, spindle range {M40..M45}; the same
; code twice is NC3001. The manual states no such error; the sets follow the cancel column.
; The error stands at the second code and names the first set of the second code that the first
; code is also in; the note points at the first code.
; These pairs conflict by the sets coolant {M09 M13 M14} and rotary clamping {M11 M12}, or are one
; code twice. Expected: NC3005 naming the function, "they control the same function (coolant)",
; "(rotary clamping)"; for one code twice NC3001 "M06 appears more than once in the block"
; (M06, M12, M60).
;
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
M06 M06
M09 M13
M13 M09
M09 M14
M14 M09
M11 M12
M12 M11
M12 M12
M60 M60
