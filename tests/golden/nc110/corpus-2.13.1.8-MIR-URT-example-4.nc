; Copy of corpus part4/2.13.1.8-MIR-URT-example-4.nc (NC-110 §2.13.1.8, example 4,
; Fig. 2.117, seed lines 8294-8318). Corrected: N104 is printed (URT,O) with the Latin
; letter O for the digit 0 (both renderings; decision 19 makes it NC3018, as in
; corpus-2.13.1.2-UOT-example-as-printed).
; The example rotates a GTL profile (c1 l1 c2 l2 c3 l3) six times by 60 degrees: a
; triangle with round corners, closed (last element c1), travelled counter-clockwise;
; G41 puts the "MILL D=8" (profile nc110-mills: radius 4) inside, so the corners' circles
; of radius 5 shrink to 1. Checked by hand: l1 = c1,c2 touches c1 at (16.970, 10.402)
; (the tangent at the centres' direction (35, 15)); moved 4 to its left it starts at
; X15.3939 Y14.0809, where N92 goes and every pass's c1 ends; N100's Z0 comes after
; the last element's move, before G20 (§2.11.8.4). Each pass is the first turned by
; E26 about the origin (URT applies when the profile runs, decision 65).
N75 (DIS,"MILL D=8")
N81  c1=I15 J15 r5
N82  c2=I50 J30 r5
N83  c3=I30 J50 r5
N84  l1=c1,c2
N85  l2=c2,c3
N86  l3=c3,c1
N87  F170S800T1.1M6 M3
N88  E26=0
N89  (RPT,6)
N90  (URT,E26)
N92  G21 G41 c1
N93  Z-10
N94  l1
N95  c2
N96  l2
N97  c3
N98  l3
N99  c1
N100 Z
N101 G20 G40 l1
N102 E26=E26+60
N103 (ERP)
N104 (URT,0)
N109 G X Y Z10 M30
