; A CAM post for Mach3 writes its header as ; comments (decision 54)
; Tool: 6 mm end mill
G21 G90 ;(METRIC) 
G00 X0 Y0; G01 X10 F300;
;
G00 Z5 ; up to the clearance
M30
