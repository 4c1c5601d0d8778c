; source: ../shared/corpus/nc110/part5/5.5-INP-example.nc (seed section 5.5)
; expect: E40 = 1000; execution stops and screen line 2 shows "FEED = 1000"; the operator may edit
; the value; on ENTER the displayed value is stored in E40 and the cycle continues.
; Changes: "Е40" of the INP block is printed with a Cyrillic Е (Latin here, decision 2); the
; dotted line before it and the annotation beside it are left out; the last block, added, shows E40.
; The operator's answer comes from the input script (decision 60): corpus-5.5-INP.input answers
; 1500; corpus-5.5-INP.enter keeps the value offered (ENTER).
E40 = 1000
(INP, "FEED = ", E40)
(DIS, E40)
