; syntax-lines-percent: % is the tape mark only alone on the first or last line; anywhere
; else it is an error (NC1001), as is the character : (Table 2.1 lists both, no NC-110
; program uses them).
%
G0 X1 %
G0 X:1
G0 X1
