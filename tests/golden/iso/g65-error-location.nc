(a run-time error inside a macro of the library is reported at the macro's file and line; a conditional G65 and M98)
G90 G01 X0 Y0 Z0 F100;
#1=0;
IF [#1 EQ 0] THEN G65 P2003 A4;
IF [#1 NE 0] THEN G65 P2003 A5;
(O2001 adds 1 to the shared #1)
IF [#1 EQ 0] THEN M98 P2001;
IF [#1 EQ 0] THEN M98 P2001;
G65 P2003 A[#1-1];
G01 Y1;
M30;
