; FLOWD (cls-depth, cls-two-levels): calls nothing.
E32=E32+1
