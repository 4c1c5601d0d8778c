; M30 keeps the corrector of the tool in the spindle (§2.7.8 L1873-1877; decisions 11, 25),
; profile motion-tools (corrector 10: length 50.5 on X).
; Expected: N1 tool_select 1, tool_change 1, tool_length_offset X50.5 Y0 Z0; N2 M30:
; spindle stop, coolant off, end information, and no tool_length_offset event (the
; length stays in force).
N1 T1.10 M6
N2 M30
