%12 "macro files that break the rules of §2.3.5"
N1 G72 L21
N2 G72 L23
N3 G72 L24
N4 G72 L25 "no such file"
N5 M30
