(G02 G03 in G17, spec 8.2: I J from the start point, an omitted one is 0; R+ an arc up to 180 degrees, R- one over 180; a full circle by I J alone; expected: centres 10,0 10,0 15,20 15,20 -5,0 0,5 5,0 10,10)
G90 G00 X0 Y0 Z0;
G02 X10 Y10 I10 J0 F100;
G03 X20 Y0 I0 J-10;
G00 X0 Y0;
G02 X40 Y20 R-25;
G02 X0 Y0 R25;
G03 I-5;
G02 J5;
G03 X10 I5;
G03 X20 Y10 R10;
M30;
