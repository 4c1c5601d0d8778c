%
; syntax-lines: how ncc reads the lines of a file (docs/dialects/nc110.md "Reading a
; program"): one block a line, a CR before LF dropped (this file has CRLF line ends),
; blank lines (also of blanks and tabs) are not blocks, a % alone on the first or last
; line (the ISO tape mark, Table 2.1 L1419) is ignored. Three rapids: X1, X2, X3.
G0 X1

   
	G0 X2
G0 X3
%
