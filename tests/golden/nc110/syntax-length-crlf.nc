; syntax-length-crlf: the CR of a CRLF line end is not part of the block (docs/dialects/
; nc110.md "Reading a program"; §2.4.4 seed L1450): a block of 128 characters before its
; CRLF is fine. E30 = 61 ones + 10 = 71.
E30=1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+10
(DIS,E30)
