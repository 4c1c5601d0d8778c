(the seed's §8.10 example with a tool of radius 5 preset as D1: the closed contour under G42, start-up on N02, outside corners, the arcs offset by 5, G40 with the last move)
G54 G90 D1;
N01 G00 X50 Y50 Z-10;
N02 G91 G42 G01 X100 Y100 F100;
N03 X100;
N04 G03 X50 Y50 R50;
N05 G01 Y100;
N06 X-150;
N07 G02 X-50 Y-50 R50;
N08 G01 Y-100;
N09 X50;
N10 G40 X-100 Y-100;
M30;
