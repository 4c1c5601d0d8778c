; Tools and correctors the profile does not have (§2.7.7; decision 11; docs/profile.md),
; profile motion-tools (tools 1 4 5 6, correctors 1 4 5 10 12), ncc check.
; Expected: N1 T7.1: NC4019 warning "tool 7 is not in the machine profile's tool table"
; (6:4); N2 T1.99: NC4020 error "corrector 99 is not in the machine profile's [offsets]"
; (7:4); N3 T6 (corrector 0, none) and N4 T5.5 are fine.
N1 T7.1
N2 T1.99
N3 T6
N4 T5.5 M6
