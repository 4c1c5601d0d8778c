; ASSET operands that break the rules of §5.3 (spec nc110-5 §6.4-6.5), each reported at its place.
; A code alone: its first operand is missing.
(OPN)
(DER)
(RED)
(CRE)
(CAN)
; Channels and structures are 0..255 (a BY constant) or an E parameter.
(OPN, 256, FILQ)
(RED, 1, -1)
(CLO, 1.5)
; A record is 1..32767 or an IN parameter (E10-E19); a record count 1..32767 or a parameter.
(RED, 1, 2, 0)
(WRT, 1, 2, 32768)
(RED, 1, 2, E25)
(CRE, 2, X, 0)
; A file is 1 to 6 capitals and digits, a letter first, on MP0..MP6.
(OPN, 1, TOOLONG)
(OPN, 1, FILQ/MP9)
(OPN, 1, filq)
(CAN, 9X)
(CAN, A B)
(CAN, ../X)
(OPN, 1, /ETC)
; R or W.
(OPN, 1, FILQ, X)
; DER binds variables of an ASSET format (IN, RE, LR, kCH: table 5.1), at most 17.
(DER, 1, E5)
(DER, 1, E20)
(DER, 1, SYVAR2)
(DER, 1, SA10.BY)
(DER, 1, SYVAR.33CH)
(DER, 1, 5)
(DER, 1, E10, E11, E12, E13, E14, E15, E16, E17, E18, E19, E25, E26, E27, E28, E29, E30, E31, E32)
; Too many operands.
(CLO, 1, 2)
(CAN, X, Y)
M30
