; NC-110 §2.8.12.1 (seed lines 4449-4480), §1.2.33, §2.13.9 (DPT motion), decision 55:
; G72 moves toward the nominal point, rapid to Qa (10) before it, at Vm to the contact
; (the probe's centre stops its radius, 2 from corrector 9, before the surface), rapid
; back to the start, and stores the contact point in E parameters from its E word, in
; the order the axes are written. Profile cycle-probe-g72 (the tool starts at 0 0 0).
; N2: G72 X100 E40: rapid to X90, probe to X97.8 (contact X99.8), rapid to X0;
;   E40 = 99.8.
; N5: from (0,0,10) toward (30,0,-40) (the Z word first): contact Z-40.5 X30.3; the
;   path is 58.3095 long: rapid to 48.3095 along it (24.855, 0, -31.4251); the probe
;   stops at the contact's projection on the path less 2 (29.271, 0, -38.785); rapid
;   back to (0,0,10); E41 = -40.5 (Z), E42 = 30.3 (X).
; N7: the list has run out: toward (50,50,10) from (0,0,10): rapid to 60.7107 along the
;   path (42.9289, 42.9289), probe to 68.7107 (48.5858, 48.5858), back; E43 = E44 = 50.
N1 T9.9 M6
N2 G72 X100 E40
N3 (DIS,E40)
N4 G Z10
N5 G 72 Z-40 X30 E41
N6 (DIS,E41," ",E42)
N7 G72 X50 Y50 E43
N8 (DIS,E43," ",E44)
