%9 "the machine's M groups M10-M13 and group M14"
N1 M20 M22 M31 "one of M10, one of M11, one of M14"
N2 M50 G74 M37 G24 G09 "G09 and G24 share group G2"
N3 M50 G74 M37 G09
N4 M20 M21 M23 M99
N5 M31 M32 "both in M14"
N6 M02 "every group to its basic state"
