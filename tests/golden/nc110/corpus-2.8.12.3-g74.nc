; Copy of corpus part2/2.8.12.3-G74-example.nc (NC-110 §2.8.12.3, seed lines 4526-4537):
; "G74 X100.2 E41, E41 = Pt - Pm", "positive if the actual coordinate is met before the
; nominal one". The contact comes from profile cycle-probe-corpus-g74: machine X100.15.
; The tool starts at 0 0 0, no corrector. Added: the DIS block shows the result.
; Checks (decision 55): rapid to X90.2 (Qa 10 before the nominal point), feed to the
; contact X100.15 (no radius correction), rapid back to X0; E41 = 100.2 - 100.15 = 0.05.
G74 X100.2 E41
N2 (DIS,E41)
