(codes that must not share a block, decision 10 and A-05: two M codes of one set, stops M00 M01 M02 M30, spindle M03 M04 M05 M06, coolant M07 M08 M09, calls M97 M98 M99, are NC3005; two G codes of one group are NC3002; EXPECTED NC3005 for M97 with M98 as for the other sets, ncc reports NC3042 citing 8.16 of G65, and also NC3010 and NC3001 for the same block)
G90 G00 X0 Y0 Z0;
M00 M01;
M02 M30;
M03 M04 S100;
M03 M05;
M05 M06;
M07 M08;
M08 M09;
M97 P10 M98 P7777;
M98 P7777 M99;
G00 G01 X1;
G17 G18;
G90 G91;
G43 G49;
G98 G99;
G94 G95;
G54 G55;
M30;
