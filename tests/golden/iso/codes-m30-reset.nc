(M30 reset, spec 8.29 and decision 11: M02 M30 restore the power-on state: the trace shows units mm, G94, G40, G49, G54, no G92 or G52 offset and no transform again, besides spindle and coolant off; G17 and G15 were restored before; EXPECTED no origin event: with a G52 shift in force at M30 ncc adds the NC-110 event origin X-125 Y-125 Z0, in canon SET_G5X_OFFSET with the number 0, which no G54-G59 has)
G90 G00 X0 Y0 Z0;
G20 G18 G55 G95 G99 G16;
G17 G15 G43 H1 Z1;
G92 X0;
G52 Y1;
G51 P2.;
G68 R10.;
G41 D1;
S100 M03 M08;
G91 G81 Z-1 R1 L0;
M30;
