(G52, spec 8.13 and decision 16: the values replace the local shift of the axes written, the others keep theirs; each of G54-G59 keeps its own shift and selecting it brings it back; G91 does not make G52 incremental; G92 ends them all; EXPECTED position_offset X0 Y0 Z0 at G55 and X10 Y20 Z5 back at G54: ncc prints no event when the work offset changes, so the trace reads as if the G54 shift stayed in force under G55, though line 10 shows G55 had none)
G90 G54 G00 X0 Y0 Z0;
G52 X10 Y20;
G00 X0 Y0;
G52 Z5;
G00 X1 Y1 Z1;
G55;
G00 X0 Y0 Z0;
G52 X-5;
G00 X0 Y0;
G54;
G00 X0 Y0 Z0;
G91 G52 X1;
G90 G00 X0 Y0 Z0;
G92 X0 Y0 Z0;
G00 X1 Y1 Z1;
M30;
