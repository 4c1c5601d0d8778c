; system-assign: the system variables a program sets in assignment blocks (§2.10 seed
; L4909-5412, Table 3.3 L11200-11345; decision 16) and reads in expressions and DIS.
; TMR UOV ERF MCD RTA RTO: LR; RMS UCV: BY; UGF: RE; USB USO UVR URL UAS UEP: 0 or 1.
; Each takes a constant or one E parameter of its class.
; the values at the start of the run (USB = 1: machine.block_skip is off; USO = 0:
; machine.optional_stop is off; RMS 100 percent; URL 1)
(DIS,TMR)
(DIS,UOV)
(DIS,RMS)
(DIS,USB)
(DIS,USO)
(DIS,UVR)
(DIS,URL)
(DIS,UAS)
(DIS,UEP)
(DIS,UCV)
(DIS,ERF)
(DIS,MCD)
(DIS,UGF)
(DIS,RTA)
(DIS,RTO)
; constants (the manual's: TMR = 12.5 L4962, UOV = 0.5 L4992, RMS = 110 L5019,
; UGF = 20.5 L5394, MCD = 2 L5333)
TMR = 12.5
UOV = 0.5
RMS = 110
UGF = 20.5
MCD = 2
ERF=0.05
UCV=2
USO=1
UVR=1
UAS=1
UEP=1
RTA=0.01
RTO=-0.02
(DIS,TMR)
(DIS,UOV)
(DIS,RMS)
(DIS,UGF)
(DIS,MCD)
(DIS,ERF)
(DIS,UCV)
(DIS,USO)
(DIS,UVR)
(DIS,UAS)
(DIS,UEP)
(DIS,RTA)
(DIS,RTO)
; one E parameter of the class (L4966 TMR = E32, L4996 UOV = E30, L5397 UGF=E26)
E32=13.4
TMR = E32
E30=1.5
UOV = E30
E26=75
UGF=E26
E5=10
RMS=E5
E1=0
USO=E1
(DIS,TMR)
(DIS,UOV)
(DIS,UGF)
(DIS,RMS)
(DIS,USO)
; read in an expression: 13.4 + 1.5 = 14.9
E40=TMR+UOV
(DIS,E40)
