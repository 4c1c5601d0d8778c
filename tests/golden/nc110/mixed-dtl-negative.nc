; A negative DTL value (NC-110 §2.13.5.2); decision 33.
; Profile frame-tolerance: Z drive error 1.
; Checks (ncc check): (DTL,Z-0.1) is an error (NC4062) at the operand, and the message
; says the tolerance must not be negative (it does not exceed the drive error).
(DTL,Z-0.1)
