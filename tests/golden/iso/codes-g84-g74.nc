(G84 G74, spec 8.26 and decision 20: G84 turns the spindle cw on the way in whatever M03 M04 said, G74 ccw, reverses at the bottom, feeds out to R and restores it, then rapids to the initial level under G98; P dwells at the bottom; with Q each peck goes out to R reversed and back in at feed; expected G84 Q4 pecks -2 -6 -10, G74 Q3 pecks -1 -4 -5)
G90 G00 X0 Y0 Z20;
S500 M04;
G98 G84 X10 Y0 Z-10 R2 F500;
G99 X20 P1.;
G80 G00 Z20;
G98 G84 X30 Z-10 R2 Q4;
G80;
G74 X40 Z-5 R2;
G99 X50 Q3;
G80;
M30;
