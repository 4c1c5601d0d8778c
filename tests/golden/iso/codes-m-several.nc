(several M codes in one block, decision 10: allowed when no two are of one set, stops, spindle, coolant, calls; the spindle starts before the motion, coolant and stop act after it)
G90 G00 X0 Y0 Z0;
S2000 M03 M08 G01 X50 F100;
M05 M09;
M04 M07 M00;
T1 M06 M08;
M30;
