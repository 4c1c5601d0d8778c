(a canned cycle in G18, spec 8.5 A-18 and decision 36: the seed says G73-G84 work only in the x-y plane, ncc drills along the normal of any plane: in G18 along Y, X and Z giving the hole position; a start below R goes up to R first, decision 18)
G90 G00 X0 Y0 Z20;
G18 G81 X10 Y-5 Z2 R5 F100;
G80 G17;
M30;
