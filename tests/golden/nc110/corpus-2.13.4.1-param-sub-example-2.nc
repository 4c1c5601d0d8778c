; corpus-2.13.4.1-param-sub-example-2: copy of corpus part4/2.13.4.1-param-sub-
; example-2-main.nc (§2.13.4.1 example 2, figure 2.128, seed L9147-9161).
; Parameters: E25 angle 30, E30/E31 first hole (12,12), E32 pitch 20, E1 = 9
; holes, E34 R = 2, E35 Z = -3 then -20, E2 cycle 81.
; With the corrected SUB600 (lib/MP0, --lib lib): each call drills 9 holes at
; (12+20k cos30, 12+20k sin30), k = 0..8, in origin-0 coordinates (12,12)
; (29.321,22) (46.641,32) ... (150.564,92); the trace shows them from the
; temporary origin (12,12), rotated: (0,0) (17.3205,10) (34.641,20) ...
; (138.5641,80); first at Z-3 (T4.4), then at Z-20 (T5.5).
; As printed (profiles/flow-mp1.toml: lib/MP1/SUB600.nc): N602 E3=E3-1 stores
; -1 into the BY parameter E3: NC4032 at SUB600 N602 (decision 8), before any
; hole (the .printed.out).
; Changed: the manual's note says the calls are N39 and N42 (they are N39 and
; N43); the elided end reads N44 G Z50 M30. Tools: profiles/flow-tools.toml.
N30 S1000 F60 T4.4 M6 M3
N31 E25=30
N32 E30=12
N33 E31=12
N34 E32=20
N35 E1=9
N36 E34=2
N37 E35=-3
N38 E2=81
N39 (CLS,SUB600)
N40 (DIS,"..........")
N41 S880 F100 T5.5 M6 M3
N42 E35=-20
N43 (CLS,SUB600)
N44 G Z50 M30
