; epp-block-numbers: EPP and branch operands are labels (§2.13.2.3 L8510-8518,
; §2.13.2.4 "МЕТКА"; decision 3). N3 and N4 below are block numbers, not labels:
; no block has the label N3 or N4, so each of the three operands is NC3010 (line 6
; col 9, line 9 cols 9 and 12), and with these static errors nothing runs.
N1 E30=1
N2 (BNC,N4)
N3 E30=5
N4 (DIS,E30)
N5 (EPP,N3,N4)
N6 M30
