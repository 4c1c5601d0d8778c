; EXE, REL, WAI and SND as ncc reads them (NC-110 §4.1, decision 63): every form of the manual's
; examples (4.1.1, 4.1.3, 4.1.4), as `ncc ir` shows them (process-operands-errors: what it refuses).
; The manual's Progl is PROG1 here, and its program of device MP2 is P800 (lib/MP2/P800.nc).
M30
(EXE,2,PROG1)
E4=2
(EXE,E4,P800/MP2)
(WAI,3)
E1=3
(WAI,E1)
(WAI,SA10.BY=2)
(WAI,SK2.IN=E11)
(WAI,SYVAR2=E5)
(WAI,SYVAR>5)
(WAI,SK2>E8)
(WAI,SA10.BY#2)
(WAI,SA12=1)
(SND,4)
E5=4
(SND,E5)
N25#(SND,2)
(REL)
