; Copy of corpus part4/2.13.1.3-UIO-example.nc (NC-110 §2.13.1.3, Fig. 2.111, seed lines
; 8000-8009). The annotations "-точка N" (point N) are dropped; the elision lines are
; replaced by G0 X0 Y0, which takes the tool to the current origin (points 1-4 of the
; figure), and by G0 Z10 after N300.
; Checks (decision 26, UIO cumulative): each UIO shifts the current origin by its values:
; point 1 (20,20), point 2 (20,-20), point 3 (-25,-20), point 4 (-25,-55) (origin
; events; the tool, at the origin, shows X0 Y0). The literal operand text ("added to
; the absolute origin") would give (20,-40), (-45,-40), (-45,-35) instead.
; N300 (UAO,0) cancels the shift: origin 0, and the tool at point 4 shows X-25 Y-55.
N65 (UIO,X20,Y20)
G0 X0 Y0
N121 (UIO,Y-40)
G0 X0 Y0
N180 (UIO,X-45)
G0 X0 Y0
N230 (UIO,Y-35)
G0 X0 Y0
N300 (UAO,0)
G0 Z10
