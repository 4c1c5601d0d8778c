; M conflict sets (NC3005): two M codes that control the same function must not share a block.
; Rule: ncc reads Table 2.3 (seed lines 1773-1833: M codes and the codes each one cancels) as the
; sets of stdlib/dialects/nc110/m_codes.tsv: stop {M00 M01 M02 M30}, spindle {M03 M04 M05 M13 M14
; M19}, mist {M07 M09}, flood {M08 M09}, clamping {M10 M11}, spindle range {M40..M45}; the same code
; twice is NC3001. The manual states no such error; the sets follow the cancel column plus meaning.
; The error stands at the second code and names the first set of the second code that the first
; code is also in; the note points at the first code.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; (Pairs of the sets coolant {M09 M13 M14} and rotary clamping {M11 M12}: mcodes-check-conflicts-names.nc.)
; M00 with each code from M00 on (sets: stop):
M00 M00
M00 M01
M00 M02
M00 M03
M00 M04
M00 M05
M00 M06
M00 M07
M00 M08
M00 M09
M00 M10
M00 M11
M00 M12
M00 M13
M00 M14
M00 M19
M00 M30
M00 M41
M00 M42
M00 M43
M00 M44
M00 M40
M00 M45
M00 M60
; M01 with each code from M01 on (sets: stop):
M01 M01
M01 M02
M01 M03
M01 M04
M01 M05
M01 M06
M01 M07
M01 M08
M01 M09
M01 M10
M01 M11
M01 M12
M01 M13
M01 M14
M01 M19
M01 M30
M01 M41
M01 M42
M01 M43
M01 M44
M01 M40
M01 M45
M01 M60
; M02 with each code from M02 on (sets: stop):
M02 M02
M02 M03
M02 M04
M02 M05
M02 M06
M02 M07
M02 M08
M02 M09
M02 M10
M02 M11
M02 M12
M02 M13
M02 M14
M02 M19
M02 M30
M02 M41
M02 M42
M02 M43
M02 M44
M02 M40
M02 M45
M02 M60
; M03 with each code from M03 on (sets: spindle):
M03 M03
M03 M04
M03 M05
M03 M06
M03 M07
M03 M08
M03 M09
M03 M10
M03 M11
M03 M12
M03 M13
M03 M14
M03 M19
M03 M30
M03 M41
M03 M42
M03 M43
M03 M44
M03 M40
M03 M45
M03 M60
; M04 with each code from M04 on (sets: spindle):
M04 M04
M04 M05
M04 M06
M04 M07
M04 M08
M04 M09
M04 M10
M04 M11
M04 M12
M04 M13
M04 M14
M04 M19
M04 M30
M04 M41
M04 M42
M04 M43
M04 M44
M04 M40
M04 M45
M04 M60
; M05 with each code from M05 on (sets: spindle):
M05 M05
M05 M06
M05 M07
M05 M08
M05 M09
M05 M10
M05 M11
M05 M12
M05 M13
M05 M14
M05 M19
M05 M30
M05 M41
M05 M42
M05 M43
M05 M44
M05 M40
M05 M45
M05 M60
; M06 with each code from M06 on (sets: none):
M06 M07
M06 M08
M06 M09
M06 M10
M06 M11
M06 M12
M06 M13
M06 M14
M06 M19
M06 M30
M06 M41
M06 M42
M06 M43
M06 M44
M06 M40
M06 M45
M06 M60
; M07 with each code from M07 on (sets: mist):
M07 M07
M07 M08
M07 M09
M07 M10
M07 M11
M07 M12
M07 M13
M07 M14
M07 M19
M07 M30
M07 M41
M07 M42
M07 M43
M07 M44
M07 M40
M07 M45
M07 M60
; M08 with each code from M08 on (sets: flood):
M08 M08
M08 M09
M08 M10
M08 M11
M08 M12
M08 M13
M08 M14
M08 M19
M08 M30
M08 M41
M08 M42
M08 M43
M08 M44
M08 M40
M08 M45
M08 M60
; M09 with each code from M09 on (sets: mist flood coolant):
M09 M09
M09 M10
M09 M11
M09 M12
M09 M19
M09 M30
M09 M41
M09 M42
M09 M43
M09 M44
M09 M40
M09 M45
M09 M60
; M10 with each code from M10 on (sets: clamping):
M10 M10
M10 M11
M10 M12
M10 M13
M10 M14
M10 M19
M10 M30
M10 M41
M10 M42
M10 M43
M10 M44
M10 M40
M10 M45
M10 M60
; M11 with each code from M11 on (sets: clamping, rotary clamping):
M11 M11
M11 M13
M11 M14
M11 M19
M11 M30
M11 M41
M11 M42
M11 M43
M11 M44
M11 M40
M11 M45
M11 M60
; M12 with each code from M12 on (sets: rotary clamping):
M12 M13
M12 M14
M12 M19
M12 M30
M12 M41
M12 M42
M12 M43
M12 M44
M12 M40
M12 M45
M12 M60
; M13 with each code from M13 on (sets: spindle coolant):
M13 M13
M13 M14
M13 M19
M13 M30
M13 M41
M13 M42
M13 M43
M13 M44
M13 M40
M13 M45
M13 M60
; M14 with each code from M14 on (sets: spindle coolant):
M14 M14
M14 M19
M14 M30
M14 M41
M14 M42
M14 M43
M14 M44
M14 M40
M14 M45
M14 M60
; M19 with each code from M19 on (sets: spindle):
M19 M19
M19 M30
M19 M41
M19 M42
M19 M43
M19 M44
M19 M40
M19 M45
M19 M60
; M30 with each code from M30 on (sets: stop):
M30 M30
M30 M41
M30 M42
M30 M43
M30 M44
M30 M40
M30 M45
M30 M60
; M41 with each code from M41 on (sets: spindle range):
M41 M41
M41 M42
M41 M43
M41 M44
M41 M40
M41 M45
M41 M60
; M42 with each code from M42 on (sets: spindle range):
M42 M42
M42 M43
M42 M44
M42 M40
M42 M45
M42 M60
; M43 with each code from M43 on (sets: spindle range):
M43 M43
M43 M44
M43 M40
M43 M45
M43 M60
; M44 with each code from M44 on (sets: spindle range):
M44 M44
M44 M40
M44 M45
M44 M60
; M40 with each code from M40 on (sets: spindle range):
M40 M40
M40 M45
M40 M60
; M45 with each code from M45 on (sets: spindle range):
M45 M45
M45 M60
