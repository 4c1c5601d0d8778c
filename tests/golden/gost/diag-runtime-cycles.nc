diag-runtime-cycles: dwells, canned cycles, tools, offsets and unused words in the dry run of ncc check (NC4015-NC4020, NC4024, NC4025, NC4027; G83 without Q)
%
N1 G01 X0 Y0 Z10 F100
N2 G04 X5 P2 (NC4015 - a dwell with axis motion)
N3 G04 (NC4016 - a dwell without its time)
N4 G81 X5 Y5 (NC4017, NC4018 - no hole bottom and no R level yet)
N5 G83 X6 Z-10 R2 (G83 without any peck increment)
N6 X7 Q-1 (NC4024 - a negative peck increment)
N7 G84 X8 (NC4027 - G84 without a spindle direction)
N8 G80
N9 T7 (NC4019 - tool 7 is not in the tool table)
N10 D9 H8 (NC4020 - offsets 9 and 8 are not in the offset table)
N11 X1 I5 R3 (NC4025 - I and R have no effect in a G01 block)
N12 M30
