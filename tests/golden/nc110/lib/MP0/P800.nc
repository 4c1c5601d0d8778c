; P800 on device MP0 (the default device): the subroutine of §2.13.2.2's call
; layout (corpus part4/2.13.2.2-CLS-example-2-P800.nc, seed L8446-8450). The
; manual elides N500-N503 ("..........", and a line of dots after them); bodies
; supplied: a message, a count of the calls in E30, a rapid move to X = E30, and
; a message with the count. The end of the file returns to the caller.
N500 (DIS,"P800 N500")
N501 E30=E30+1
N502 G XE30
N503 (DIS,"P800 N503 ",E30)
;...............
