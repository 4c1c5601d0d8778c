; expressions-div-zero: division by zero is a run-time error at the block (§2.12;
; digest §4.6; NC4030). E31 is 0 at the start; the message before the error is shown and
; the run stops at line 8.
E30=1/(2-1.5)
(DIS,E30)
E32=0*E31
; error here
E33=1/E31
(DIS,E33)
