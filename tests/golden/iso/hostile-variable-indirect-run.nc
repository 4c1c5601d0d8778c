(an index computed at run time: 2^32 + 1 must not wrap around to #1)
#1=5
#2=4294967297
G01 X#[#2] F100
M30
