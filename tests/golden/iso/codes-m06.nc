(M06, spec 8.31 and decision 29: M06 with no T or with the tool in the spindle does nothing; otherwise spindle and coolant off, the tool axis up to the reference Z0 at rapid, the change, and G41 and G43 end without resuming; T alone only selects; the G01 mode stays; a T not in the profile's tools is warned NC4019; EXPECTED one cutter_comp off and one tool_length_offset event at line 10, ncc prints them twice, and the rise to Z0 happens with the Z75 length offset still on)
G90 G00 X10 Y10 Z50;
M06;
T1 M06;
T1 M06;
S1000 M03 M08;
G43 H1 Z20;
G41 D1 G01 F100;
T2 M06;
G01 X30;
T2;
M06;
T3 D3 M06;
T9 M06;
M30;
