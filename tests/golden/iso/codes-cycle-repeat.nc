(L and K repeats and L0, spec 8.23 and decision 18: under G91 each repeat moves by X Y from the last hole, R from the initial level and Z from R; K is L; L0 only stores the words, X and Y of an L0 block are warned as unused; under G90 L2 drills the same hole twice)
G90 G00 X0 Y0 Z20;
G91 G99 G81 X10 Z-12 R-15 L3 F100;
G90 G80 G00 Z20;
G91 G98 G81 Y10 Z-12 R-15 K2;
G90 G81 X50 Y50 Z-3 R2 L0;
X60;
G91 X5 L0;
G90 X70 Y0 L2;
G80;
M30;
