; G codes not decoded: §2.8 (seed lines 1894-1900): "theoretically 100 G codes exist (G00-G99),
; but only part of them are decoded"; the decoded ones are the 42 of Table 2.2 (lines 1583-1685;
; stdlib/dialects/nc110/g_codes.tsv). Each of the other 58 numbers is NC3003 at its word, also in
; a block with a decoded code (which is then not checked against it) and in its one-digit form.
; Known problem of the .out: NC3003 says "G05 is not defined and the machine profile does not
; define it", but an NC-110 profile cannot define G codes (no such key; [gost] tables is GOST only);
; expected e.g. "G05 is not a G code of the NC-110 (Table 2.2)". Also: 58 + 5 NC3003 and line 75's NC3013.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
G05 X10
G07 X10
G08 X10
G10 X10
G11 X10
G12 X10
G13 X10
G14 X10
G15 X10
G16 X10
G22 X10
G23 X10
G24 X10
G25 X10
G26 X10
G30 X10
G31 X10
G32 X10
G36 X10
G37 X10
G38 X10
G39 X10
G43 X10
G44 X10
G45 X10
G46 X10
G47 X10
G48 X10
G49 X10
G50 X10
G51 X10
G52 X10
G53 X10
G54 X10
G55 X10
G56 X10
G57 X10
G58 X10
G59 X10
G60 X10
G61 X10
G62 X10
G63 X10
G64 X10
G65 X10
G66 X10
G67 X10
G68 X10
G69 X10
G75 X10
G76 X10
G77 X10
G78 X10
G87 X10
G88 X10
G92 X10
G98 X10
G99 X10
; One digit: G5 is G05, G7 is G07.
G5 X10
G7
; With decoded codes before and after it.
G00 G05 X10
G87 G01 X10 F100
G90 G99 G91
