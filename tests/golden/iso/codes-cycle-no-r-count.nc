(a canned cycle without R: NC4018 once, with the count of the holes after it, decision 74)
G90 G00 X0 Y0 Z10
G81 Z-5 F100
X10
X20
X30 R2
X40
G80
M30
