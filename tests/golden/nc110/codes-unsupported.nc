; The three-letter codes of the parts of the manual ncc does not implement yet: tool life (TOF,
; §2.13.10), tool correctors (RQU RQP, §2.13.8), probe settings (DPT, §2.13.9) and virtual axes
; (UAV, §2.17). (ASSET files: asset-operands; INP: corpus-5.5-INP, inp-errors; the user screen:
; screen-errors; processes: process-operands; the graphic display: graphic-display.)
; docs/dialects/nc110.md: they parse and are reported as not supported yet (NC3034 at the code, with
; the meaning of three_letter_codes.tsv); their operands are not read. First each code alone, then
; each as the manual writes it (seed lines in the comments), with leading fields where it has them.
; The first block ends the run (M30): the blocks below are read and checked, not run (§2.15).
M30
(TOF)
(RQU)
(RQP)
(DPT)
(UAV)
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
; seed line 10952
(UAV, 1, XC, UV, E40)
