(G28 G29, spec 8.8 8.9 and decision 17: G28 words are the intermediate point in G90 or G91, then the named axes rapid to the reference point, machine 0 = work X125 Y125 Z0 in G54; G29 goes through the intermediate point on its named axes, then to its words, read in G91 from the intermediate point; G29 without words ends at the intermediate point; G28 without words sends all axes to the reference directly; expected: 50,20,40 then 125,20,0; 50,20,40 then 0,0,5; 0,0,15 then 0,0,0; 0,0,15 then 10,0,10; 50,60,70 then 125,125,0; 50,60,70; 125,125,0)
G90 G00 X10 Y20 Z30;
G28 X50 Z40;
G29 X0 Y0 Z5;
G91 G28 Z10;
G29 X10 Z-5;
G90 G28 X50 Y60 Z70;
G29;
G28;
M30;
