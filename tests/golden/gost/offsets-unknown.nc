offsets-unknown: a G54-G59 whose preset offset is not in the profile's [work_offsets] is NC4020 (docs/profile.md)
%
N1 G54 G00 X0 Y0 (offset 1 exists)
N2 G55 (offset 2 exists)
N3 G56 (offset 3 does not)
N4 G59 X10. (nor does offset 6)
N5 M30
