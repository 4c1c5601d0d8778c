(D and H are separate offsets, decision 58, as on Fanuc and LinuxCNC: H selects the length of G43, D the radius of G41; the profile's offsets are 1 = length 75 radius 5, 2 = length 110 radius 4.25. G41 without any D takes D0's radius 0, not H2's; G41 D1 keeps H2's length; G41 D0 ends the radius, not the length; H0 ends the length, not the radius)
G90 G00 X0 Y0 Z100;
G43 H2 Z50;
G41 G01 X10 F100;
G40 X0;
G41 D1 X10;
Y10;
G40 X0 Y0;
G41 D0 X10;
G40 X0;
G41 D1 X10;
H0 Y10;
G40 X0 Y0;
M30;
