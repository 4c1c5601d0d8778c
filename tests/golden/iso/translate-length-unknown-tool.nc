(translate-length-unknown-tool: without a tool change before it the tool in the spindle is not known, so ISO's G43 has no NC-110 M06 to become)
G90 G17 G00 X0 Y0 Z100
G43 H2 Z50
M30
