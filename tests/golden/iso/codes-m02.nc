(M02, spec 8.29: it acts after the rest of its block, ends the program and switches the spindle and coolant off; the blocks after it are not run)
G90 G00 X0 Y0 Z0;
S1000 M03 M08;
G01 X10 F100 M02;
G01 X20;
