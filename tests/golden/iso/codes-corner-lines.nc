(chamfer and fillet between lines, spec 8.3 A-15: ,C is the straight distance from the corner along each element, ncc's choice, ,R a tangent arc; expected: chamfer 15,0 to 20,5; fillet 20,15 to 15,20 about 15,15; in G18 chamfer X18 to Z-2; under G68 90 about 0,0 the corner turns too)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,C5;
Y20 ,R5;
X0;
G00 X0 Y0 Z0;
G18 G01 X20 ,C2;
Z-10;
G17 G00 X0 Y0 Z0;
G68 X0 Y0 R90.;
G01 X20 ,C2;
Y10;
G69;
M30;
