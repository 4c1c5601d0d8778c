; corpus-2.13.2.2-cls-example-1: copy of corpus part4/2.13.2.2-CLS-example-1.nc
; (§2.13.2.2, seed L8438-8440 / L15801): "transfers control to the subroutine
; P800 on the memory device MP2". P800 is lib/MP2/P800.nc (body supplied: a
; message and a move to X80). Expected: P800's events from lib/MP2/P800.nc,
; then the return to N2.
; Changed: the manual's annotation after the block is dropped; N2 M30 added
; (the manual's fragment has no end).
N1 (CLS,P800/MP2)
N2 M30
