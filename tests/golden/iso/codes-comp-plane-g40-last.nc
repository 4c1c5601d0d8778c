(a plane code then G40 in one block under G41, spec 1.8: word order is free; ncc rejects G19 G40 with E-10 NC4064 though it accepts G40 G19 in codes-comp-plane-g40-first: EXPECTED one answer for both orders; D0 keeps the path programmed)
G90 G00 X0 Y0 Z0;
G41 D0 G01 X10 F100;
G19 G40;
G17 G01 Y10;
M30;
