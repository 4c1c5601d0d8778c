; M30 ends the run and resets the control (NC-110 §2.6, §2.7.8: "M30: automatic RESET,
; origin 0 confirmed", seed line 1873; §2.13.1.1 L7891, §2.13.1.5 L8094); decision 25
; (M02 and M30 alike).
; Profile frame-origins: origin 1 = X100 Y200 Z-50 B10.
; Checks: before M30 the program selects origin 1 shifted by UIO, mirror Y, scale 2 on
; X Y Z, rotation 30, the plane ZX (DPI), inches, G91, feed per revolution and constant
; cutting speed, the spindle and the coolant on; G91 G0 X0 moves nothing and shows the
; tool, at machine zero, in inches from the origin. At M30, after its block: the
; spindle and the coolant stop, the power-on codes come back (units mm, plane XY, feed
; per minute, rpm), origin 0 on every axis (X0 Y0 Z0 B0), no transform; then
; "end information".
(UAO,1)
(UIO,X5)
(MIR,Y)
(SCF,2,X,Y,Z)
(URT,30)
(DPI,Z,X)
G70 G91 G95 G96
S100 M3
M8
G0 X0
M30
