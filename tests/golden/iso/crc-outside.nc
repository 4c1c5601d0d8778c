(G42 in a block of its own: a right-angle entry; outside corners get an arc of the radius about the corner; an arc offset outwards; G40 alone: a right-angle exit back to the path)
G17 G90 G00 X-10 Y-10 Z0;
G42 D1;
G01 X0 Y0 F100;
X20;
Y20;
G03 X0 Y20 R10;
G01 Y0;
G40;
G00 X-10 Y-10;
M30;
