; The three-letter codes of the parts of the manual ncc does not implement yet: tool life (TOF,
; §2.13.10), tool correctors (RQU RQP, §2.13.8), probe settings (DPT, §2.13.9), graphics (UCG CLG
; DCG, §2.13.7), virtual axes (UAV, §2.17) and processes (EXE REL WAI SND, §4.1). (ASSET
; files: asset-operands; INP: corpus-5.5-INP, inp-errors; the user screen: screen-errors.)
; docs/dialects/nc110.md: they parse and are reported as not supported yet (NC3034 at the code, with
; the meaning of three_letter_codes.tsv); their operands are not read. First each code alone, then
; each as the manual writes it (seed lines in the comments), with leading fields where it has them.
; The first block ends the run (M30): the blocks below are read and checked, not run (§2.15).
; Known problem: the .out cites CLG §2.13.7.3, UAV §2.13.11, EXE-SND §2.16, INP-OUT chapter 4.
M30
(TOF)
(RQU)
(RQP)
(DPT)
(UCG)
(CLG)
(DCG)
(UAV)
(EXE)
(REL)
(WAI)
(SND)
; seed line 10442
"A3" N2101 (TOF,13)
; seed line 7788
(TOF,E11)
; seed line 10773
N88 # (RQU,1,1,ZE30)
; seed line 10226
N32  (RQP,30,30,ZE35)
; seed line 10133
(DPT,10,12,1000)
; seed line 9778
N8  (CLG)
; seed line 9779
N9  (DCG)
; seed line 10952
(UAV, 1, XC, UV, E40)
; seed line 11597 (the manual's Progl read as PROG1)
(EXE,2,PROG1)
; seed line 11633
(WAI,3)
; seed line 11716 without its final full stop
N25#(SND,2)
; seed line 13072
