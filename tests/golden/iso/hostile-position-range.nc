(a position beyond any machine's reach is refused, written or computed: NC4094)
G91 G01 X6000000000 F100
X6000000000 (12,000 km: refused, X stays)
#1=[10000000000*10000000000]
G90 Y#1
X[#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1*#1]
X1 Y1
M30
