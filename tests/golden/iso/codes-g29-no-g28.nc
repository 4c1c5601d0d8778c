(G29 with no intermediate point, decision 17: G29 without an earlier G28 is NC4082 at run time; a G28 without words keeps no intermediate point, so a G29 after it is NC4082 too; check reports both)
G90 G00 X10 Y20 Z30;
G29 X0;
G28;
G29;
M30;
