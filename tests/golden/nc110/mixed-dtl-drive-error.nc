; DTL values above the drive error (NC-110 §2.13.5.2, seed lines 9426-9430: "the
; tolerance must not exceed the current drive error"); decision 33: NC4062.
; Profile frame-tolerance: X drive error 0.5 mm (0.0197 inch).
; Checks (ncc check's dry run reports each): (DTL,X0.6) exceeds 0.5: NC4062 at the
; operand; under G70 (DTL,X0.02) is 0.508 mm: NC4062 with the values in inches.
(DTL,X0.6)
G70
(DTL,X0.02)
