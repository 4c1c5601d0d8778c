; asset-unprepared: `ncc run --files DIR` on a directory that `ncc files init` has not
; prepared (no device folder MP0..MP6): a warning says so and how to prepare it
; (NC6013, decision 78), once, besides the statement's own code 15 (invalid device).
(OPN,1,FILE1,R)
