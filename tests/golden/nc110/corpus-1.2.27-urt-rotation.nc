; Copy of corpus part1/1.2.27-urt-rotation.nc (NC-110 §1.2.27, seed line 721; the rule
; is §2.13.1.5, lines 8070-8110). Added: moves after the rotation and (URT,0).
; Checks: (URT,45) rotates the programmed geometry by 45 degrees ("degrees and tenths",
; L8082) counter-clockwise (decision 28) about the current origin (origin 0 here):
; G1 X10 goes to X7.0711 Y7.0711; Y is not written and stays 0 in program coordinates
; (decision 29). G0 X0 Y10 goes to X-7.0711 Y7.0711. After (URT,0), G0 X10 Y0 is
; X10 Y0 again (unrotated).
(URT,45)
G1 X10 F100
G0 X0 Y10
(URT,0)
G0 X10 Y0
