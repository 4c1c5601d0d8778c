; NC-110 §2.13.8-2.13.10: what RQU, RQP, TOF and DPT refuse, once each, at the operand.
; Profile tooling (correctors 1, 11, 30; tools 10, 110, 30).
; N1 corrector 5 is not in the table; N2 corrector 1's length applies to Z; N3 a
; corrector has one length; N4 K twice; N5 tool 0; N6 E3 is BY; N7 TOF takes IN;
; N8, N9 operands missing; N10 a distance of 0; N12 the same from an E parameter, at
; run time; N14 a negative diameter (10 - 12); N15 the manual's ';' (a misprint for
; ','); line 17 the keyboard's form of DPT (§2.15.1.1); N16 Q is no axis here; N17 a
; tool is whole. N1 and N2 also want # (their values are not measured): one warning,
; at N1, that counts N2; N13 has it.
N1 (RQU,10,5,Z0.1)
N2 (RQU,10,1,X0.1)
N3 #(RQU,10,1,Z0.1,Y0.2)
N4 #(RQU,10,1,K0.1,K0.2)
N5 (RQU,0,1,Z0.1)
N6 (RQU,10,1,ZE3)
N7 (TOF,E1)
N8 (TOF)
N9 (DPT,10,12)
N10 (DPT,0,12,600)
N11 E30=0
N12 (DPT,10,E30,600)
N13 # (RQP,10,1,Z-9999)
N14 # (RQP,10,1,K-12)
N15 (RQU,10,1,ZE40; KE41)
DPT, 10, 12, 1000
N16 (RQP,10,1,Q1)
N17 (TOF,12.5)
N18 M30
