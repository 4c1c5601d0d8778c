(G53 errors, spec 8.14 E-20 E-21 and decisions 27 32: G53 under G91 is NC4064, not with a G90 of its block; G53 with G28, G92 or G29 in its block is NC3013, and ncc adds NC3002 as both are group 00, one problem reported twice)
G90 G00 X0 Y0 Z0;
G91 G53 X0;
G53 G90 X0;
G90 G53 G28 X0;
G53 X0 G92 X0;
G53 G29 X0;
M30;
