; NC-110 §2.13.10 (seed lines 9910-9930): "(TOF, 22)", "(TOF, E11)": tools 22 and the
; one E11 holds are declared unusable. E11 = 30 (the tooling profile's probe); tool
; 22 is not in the profile's table: NC4019, as T22 would be.
E11=30
(TOF, 22)
(TOF, E11)
