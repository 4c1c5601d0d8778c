(chamfer and fillet with arcs, spec 8.3: line-arc fillet R2 at 20,0 about 18.1678,2; arc-line chamfer C3 from 39.55,2.9661 to 42.1213,-2.1213; line-arc chamfer C2 from 48.5858,-8.5858 to 50.2,-11.99; arc-arc fillet R3 about 72.5277,-13.4723 from 69.6367,-12.671 to 73.611,-10.6747; the arcs are shortened, centres kept)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,R2;
G02 X40 Y0 R10 ,C3;
G01 X50 Y-10 ,C2;
G03 X70 Y-10 R10 ,R3;
G02 X80 Y-20 R10;
M30;
