(G28 G29 under G43, spec 8.8 8.9: the length offset is zeroed on the segment to the reference point and restored after, with G49 in the G28 block it is zeroed already on the way to the intermediate point; EXPECTED a tool_length_offset Z0 before the move to the reference Z and Z75 again after, or the reference Z less the offset as LinuxCNC prints it; ncc keeps Z75 in force and prints Z0, which puts the gauge point 75 mm above the reference)
G90 G00 X10 Y20 Z30;
G43 H1 Z50;
G28 Z60;
G29 Z40;
G49 G28 Z70;
G01 Z10 F100;
M30;
