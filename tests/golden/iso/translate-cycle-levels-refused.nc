(translate-cycle-levels-refused: what NC-110's two-level cycles cannot say of ISO's: a depth alone drills where the tool is in ISO, it sets the depth only in NC-110, so that hole is written as its moves; under G91 ISO reads R and Z as increments, NC-110 as levels, which is refused)
G90 G17 G00 X0 Y0 Z50
G99 G81 X10 Y10 R2 Z-5 F100
Z-8
G80
G91 G99 G81 X10 R-48 Z-7
G90 G80
M30
