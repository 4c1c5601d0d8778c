; NC-110 §2.17.1.1 (seed lines 10855-10870) as printed: the OCR's C-, VO, UOV-20 and
; 125 (for C0, V0, U0 V-20 and I25), each refused where it stands.
N5  G0 C- X80 S2000 M3 M8
N11 l2=U-15 VO,a-90
N12 l3=UOV-20,a0
N13 c2=125 J-30 r-25
