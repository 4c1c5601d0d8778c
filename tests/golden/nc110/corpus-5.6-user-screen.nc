; source: ../shared/corpus/nc110/part5/5.6-user-screen-example.nc (seed section 5.6.2.3, figures
; 5.1, 5.2)
; expect: (SCR, ON) enables the user screen (video frame 8) for the process; DEF defines 6 fields:
; 1 = "Размер Х = " at row 3 col 10, 2 = value 0 format 6 at row 3 col 19, 3 = "Размер Z = " at
; row 4 col 10, 4 = value 0 format 6 at row 4 col 19, 5 = "Скорость = " at row 5 col 10, 6 =
; value 0 format 5 at row 5 col 19.
; expect: (OUT) displays all defined fields (figure 5.2 shows "Скорость = 0", "Размер Х = 0",
; "Размер Z = 0").
; expect: INP loop: value for field 2 -> E40, field 4 -> E41, field 6 -> E29 (each shown on
; screen); if E29 = 0 -> END (G M30); otherwise G1 XE40 ZE41 FE29 and jump to ENTRY.
; Changes: the comments after the blocks are left out (decision 5); the label ENTRY, which the
; printed fragment lacks, stands on the first INP (the spec's reading). As printed, the value
; fields start at column 19, inside their 11-character captions (columns 10-20): they cover
; "= " (the screen shows "Размер Х 0"; figure 5.2 shows "Размер Х = 0" — spec open question 17,
; kept as printed). The operator (corpus-5.6-user-screen.input) enters X 120, Z -5, feed 300,
; then keeps X and Z (ENTER) and ends with feed 0.
(SCR, ON)
(DEF, 1, 3, 10, "Размер Х = ")
(DEF, 2, 3, 19, 0, 6)
(DEF, 3, 4, 10, "Размер Z = ")
(DEF, 4, 4, 19, 0, 6)
(DEF, 5, 5, 10, "Скорость = ")
(DEF, 6, 5, 19, 0, 5)
(OUT)
"ENTRY" (INP, 1,E40, 2)
(INP, 3, E41, 4)
(INP, 5, E29, 6)
(BEQ, E29, 0, END)
G1 XE40 ZE41 FE29
(BNC, ENTRY)
"END" G M30
