; Incremental moves in a transformed frame (NC-110 §2.13.1, §2.8.1); decision 29: each
; block takes the current position in program coordinates (the machine position mapped
; back through the frame); G91 words add to it, and the result is mapped forward.
; Checks (rotation 30 about origin 0):
; - G91 X20 twice: (20,0) then (40,0) rotated: X17.3205 Y10, X34.641 Y20;
; - (MIR,Y) then Y10: the program position is (40,0), plus Y10 is (40,10), mirrored
;   (40,-10), rotated X39.641 Y11.3397;
; - (SCF,2,X,Y) then X5: the program position is (20,5), plus X5 is (25,5), scaled
;   (50,10), mirrored and rotated X48.3013 Y16.3397;
; - G90 Y0: (25,0) scaled, mirrored, rotated X43.3013 Y25 (X stays 25 in the program).
F100
(URT,30)
G0 X0 Y0
G91 X20
X20
(MIR,Y)
Y10
(SCF,2,X,Y)
X5
G90 Y0
