%9 "the machine's M groups M10-M13 and group M14"
N1 M20 M22 M31 "one of M10, one of M11, one of M14"
N2 M50 G74 M37 G24 G01 X10 F100
N3 M02 "every group to its basic state"
