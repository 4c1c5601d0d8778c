; Built from the listing of NC-110 §2.13.1.8, example 3, Fig. 2.116 (seed lines
; 8265-8279 and 15680-15694; part4 of the corpus lacks it). The elision line after N15
; is dropped. Corrected: N1 is printed (DIS"...") in both renderings, without the
; comma and with typographic quotes; here (DIS,"...") (the printed form is
; corpus-2.13.1.8-MIR-URT-example-3-as-printed). Added: N16 shows E25.
; Checks (decision 20: (RPT,8) runs the body 8 times; decision 28): each pass rotates
; by E25 = 0, 45, ..., 315 degrees about origin 0 and cuts one radial slot from radius
; 40 to 80: N6 "G X40 Y" (bare Y is 0) to (40cos a, 40sin a), e.g. at 45 degrees
; X28.2843 Y28.2843; Z2; G29 G1 Z-6; X80 to (80cos a, 80sin a), e.g. X56.5685
; Y56.5685; Z-12; back to radius 40; G Z20. N15 (URT,0) cancels the rotation;
; E25 = 360 at the end (N16).
N1  (DIS,"...")
N2  S1500 T5.5 M6 M3
N3  E25=0
N4  (RPT,8)
N5  (URT,E25)
N6  G X40 Y
N7  Z2
N8  G29 G1 Z-6 F150
N9  X80 F200
N10 Z-12 F150
N11 X40 F200
N12 G Z20
N13 E25=E25+45
N14 (ERP)
N15 (URT,0)
N16 (DIS,E25)
