; parameters-places: where a word takes an E parameter it takes the class Table 2.9 names
; (seed L7761-7827; decision 14, NC2016): G M BY; S T IN; F RE; the axes RE or LR;
; I J K R t LR; TMR UOV LR, RMS UCV and the flags BY, UGF RE (§2.10). A sign before an E
; parameter is NC2018 (use NEG); an E beyond nc110.e_count is NC2017 (E0..E999).
; wrong classes in words
ME10
G0 XE1
G0 XE10
G0 XE20
G0 X1 IE25
G0 X1 KE25
SE25
SE1
SE20
FE10
G1 X1 FE1
TE30
TE14.E1
G1 X1 F100 tE25
; wrong classes for system variables
TMR=E1
UOV=E25
RMS=E30
UGF=E30
UCV=E10
USB=E30
; a sign before an E parameter, in words (an expression may negate: E1=-E2 is fine)
G0 X-E30
G0 X+E30
S-E10
E1=-E2
; E1000 does not exist, as a word value, as a target and in an expression
G0 XE1000
E1000=1
E1=E1000
; the right classes: no error (Table 2.9's examples, L7779-7827); R K I J in G0: NC4025 warnings
GE1 XE32
ME3
TE14.E15
SE15
FE27
G0 XE25 YE30 ZE999 RE33
G0 KE34 I E35 JE 36
TMR=E38
UOV=E40
RMS=E5
UGF=E28
USB=E1
