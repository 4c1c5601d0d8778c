; T is tool.corrector; the corrector takes effect at M06 (§2.7.7 L1748-1766, §2.7.8
; L1845-1849; decision 11), profile motion-tools: corrector 1 length 75 (Z), 4 length
; 120.5 (Z), 10 length 50.5 on X, 12 length 20 on U.
; N1 T1.10 selects tool 1 and corrector 10: nothing takes effect yet.
; N3 M06 loads tool 1 and corrector 10: tool_length_offset X50.5 (its [offsets] axis).
; N5 T6 = corrector 0 (none): M06 clears the length (X0 Y0 Z0).
; N6 T1.1: corrector 1, Z75.  N7 T1.12: corrector 12 on U: U20.
; N8 T1.0001: the digits after the point are the corrector number, 1: Z75.
; N9 M06 acts after the block's motion (Table 2.3): select, rapid, change, length Z120.5.
N1 T1.10
N2 G0 X10
N3 M06
N4 T6
N5 M6
N6 T1.1 M6
N7 T1.12 M6
N8 T1.0001 M6
N9 G0 X20 T4.4 M6
