; syntax-leading: the leading fields of §2.4.4 (seed L1449-1497) and §2.16 (L10727-10738)
; in their order '/', "LABEL", N, '#' or '&', with blanks between any tokens.
; Decision 7: N has up to four digits, is optional and may repeat or go down.
; Decision 18: '#' and '&' change nothing (every block is evaluated after the motion
; before it has ended).
N20 G0 X1
N10 G0 X2
N10 # G0 X3
"A" N9999 & G0 X4
N0 # E1=5
; all four fields, no blanks (L834 form): message E1=5, block N7
/"B"N7#(DIS,E1)
; leading zeros of N: shown as N7
N0007 G0 X5
; blanks everywhere (L1496 "INIZIO" N 125, L882 G 72): rapid to X6
  "INIZIO"  N 125   G 0   X 6
; no blanks at all (L1473)
/N100G00X100
; no block number at all
G0 X7
