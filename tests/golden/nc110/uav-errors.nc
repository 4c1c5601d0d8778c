; NC-110 UAV (§2.17-2.19), decision 83: what the compiler refuses (N1-N11, NC3016,
; NC3017, NC3018, NC2016) and what the run does (N12 on, NC4107). Profile uav (C and
; B rotary).
; N1 no mode; N2 mode 5; N3 mode 1 without r; N4 one real axis; N5 two virtual axes
; in mode 2; N6 a master's place 4 of 3; N7 a mirror 3; N8 C in both lists; N9 Q is
; no axis here; N10 the mode from a parameter; N11 a sixth operand.
; N12 nothing to cancel; N13 Y is not rotary; N14 C is not linear; N15 a cylinder of
; radius 0. N16-N17: C30 goes to C0 first (a rapid of its own), then U5 V0: N18's
; line from U5 passes 5 from the centre, inside 10. N19 X is the virtual axes' now.
; N20 mode 2 while mode 1 is on. N22 cancels under G41: G40 first. N24 cancels; N25
; finds the slave V at -30, not 0.
N1 (UAV)
N2 (UAV,5)
N3 (UAV,1,XC,UV)
N4 (UAV,1,X,UV,10)
N5 (UAV,2,B,VW,60)
N6 (UAV,3,VWU,XYZ,124,212)
N7 (UAV,3,VW,XY,12,13)
N8 (UAV,1,XC,CV,10)
N9 (UAV,1,XQ,UV,10)
N10 (UAV,E1,XC,UV,10)
N11 (UAV,1,XC,UV,10,5)
N12 (UAV,0)
N13 (UAV,1,XY,UV,10)
N14 (UAV,1,CX,UV,10)
N15 (UAV,2,B,V,0)
N16 G X5 C30
N17 (UAV,1,XC,UV,10)
N18 G1 U20 F100
N19 G X10
N20 (UAV,2,B,V,60)
N21 G41 G1 U30 V10
N22 (UAV,0)
N23 G40 G1 U40 V10
N24 (UAV,0)
N25 G X30 V-30
N26 (UAV,3,V,X,1,1)
N27 M30
