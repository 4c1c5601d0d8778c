; NC-110 §2.8.12, decision 55 (profile probe.contacts): G73 takes the next contact as
; the hole it finds (a circle), G72/G74 as a point; a contact of the other kind is an
; error of the test setup, and G72 at the nominal point has no direction to probe.
; Profile cycle-probe-kind. Expected (ncc check): three errors, each saying what is
; wrong in plain words, not NC4070's "made no contact (between <what> and <what>)"
; with sentences in place of the two points:
;   10:1 G73: the next probe contact (probe.contacts[0]) is a point; G73 needs a circle;
;   11:1 G72: the next probe contact (probe.contacts[1]) is a circle; G72 needs a point;
;   12:1 G72: the nominal point X0 Y0 Z0 is where the probe is: no direction to probe.
G73 r10 E40
G72 X10 E40
G72 X0 E40
