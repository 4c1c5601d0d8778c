; Called by reset-m02-cls.nc: sets a rotation and an origin shift, then M02 ends the
; whole run (decision 21: M02/M30 in a called program end the run; decision 25).
G0 X10
(URT,45)
(UIO,X5)
M02
