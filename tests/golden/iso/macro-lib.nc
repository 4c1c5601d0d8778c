(Called programs in a library folder, decision 72: 3001.nc by its number,)
(gauge_tool_o1002.cnc by the O number it starts with, o9010.NC in any case)
G90G0X0Y0Z0
G65P3001A6.B2.
M98P1002
G65P9010Z1.
M30
