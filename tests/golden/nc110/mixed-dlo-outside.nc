; DLO set while the tool is outside the new field (NC-110 §2.13.5.3); decision 34:
; "leaving the field is NC4059".
; Checks: the tool at X-100, (DLO,X-50 X100); G0 X0 brings it into the field and does
; not leave it: allowed (rapid X0); G0 X-60 leaves it: NC4059, "it reaches -60".
G0 X-100
(DLO,X-50 X100)
G0 X0
G0 X-60
