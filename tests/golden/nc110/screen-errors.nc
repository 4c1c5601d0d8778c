; SCR, DEF and OUT operands that break the rules of §5.6.2 (decision 61), each at its place.
(SCR, MAYBE)
(DEF, 1, 21, 10, "X")
(DEF, 1, 3, 65, "X")
(DEF, 1, 3, 10, 0, 8)
(DEF, 1, 3, 10, 0, 3, B)
(DEF, 1, 3, 10, 0, 3, A256)
(DEF, 1, 3)
(OUT, 1, 2, 3, 4, 5, 6, 7)
(OUT, 0, 1, 2)
(OUT, X)
M30
